#pragma once
#include <vector>

#include <Eigen/Core>

#include "engine/geom/se3.h"
#include "engine/graph/pose_graph.h"
#include "engine/pipeline/planar_kalman.h"

namespace hdprior {

struct Keyframe;

// How far the odometry drifts, as the priors see it. The graph's drift model (per-metre sigmas)
// decides how far the priors may move the odometry, and one model cannot serve every log: a good
// odometry must stay where it is, a drifting one be pulled to the map. Each candidate model (the
// configured per-metre sigmas times a factor, 0.01 to 1000 in quarter decades) runs a planar
// Kalman filter from the start over the odometry steps and the priors the graph takes; the tightest
// candidate within the margin of the likeliest (the product of the priors' innovation densities) is
// the model for the final solve. Tighter means the odometry is kept where the priors cannot tell
// it is wrong.
// With a map error length the filters carry the map's offset as the graph does, so that a run of
// priors sharing one map error is not read as drift; each factor is then tried with the map error
// as that field and as independent per prior (a map better than its sigma, where the field would
// take a real drift for the map's), and the final solve takes the map error model too.
class DriftModelLikelihood {
 public:
  DriftModelLikelihood(const PoseGraphOptions& configured, const Eigen::Vector3d& start);

  void step(const Keyframe& keyframe);
  void observe(const PosePrior& prior);
  // After a run of priors the innovation gate re-anchored on (InnovationGate): each filter starts
  // again at the prior. The prior still counts for every candidate: after a stretch without priors
  // it is the one sign of how far the odometry drifted there, and without it a drifting odometry
  // was scored only on the priors close together after it, which no candidate tells apart. From
  // then on no candidate tighter than the configured model is picked.
  void restartAt(const PosePrior& prior);

  // The configured options with the likeliest candidate's per-metre sigmas and map error length.
  PoseGraphOptions likeliest() const;

  struct Candidate {
    double factor = 1.0;          // times the configured per-metre sigmas
    double mapErrorLength = 0.0;  // the configured one, or 0 (independent)
    double logLikelihood = 0.0;   // of the priors so far, under this candidate (nats)
    bool chosen = false;          // the one likeliest() picks
  };
  // Every candidate with its log-likelihood and the one chosen: how clearly the pick won.
  std::vector<Candidate> scored() const;

 private:
  PoseGraphOptions candidate(size_t i) const;
  size_t pick() const;

  PoseGraphOptions configured_;
  std::vector<Candidate> candidates_;
  std::vector<PlanarKalman> filters_;
  bool restarted_ = false;
};

}  // namespace hdprior
