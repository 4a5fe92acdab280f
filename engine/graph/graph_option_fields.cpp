#include "engine/graph/pose_graph.h"

namespace hdprior {

std::vector<OptionField> optionFields(PosePriorOptions& o) {
  return {
      {"altitude_sigma", &o.altitudeSigma, "(0, 100]", "m", "the ground-height raster's accuracy: the altitude prior's sigma"},
      {"along_track_sigma", &o.alongTrackSigma, "[0, 1000]", "m", "added to a prior's sigma along the heading (junction matches are biased there)"},
      {"innovation_gate_probability", &o.innovationGateProbability, "[0, 1)", "", "a prior enters the graph only inside this chi-square quantile of its innovation (0: all)"},
      {"reanchor_priors", &o.reanchorPriors, "[0, 1000]", "", "this many gated priors agreeing with one another re-anchor the gate (0: never)"}};
}

std::vector<OptionField> optionFields(PoseGraphOptions& o) {
  return {
      {"prior_huber", &o.priorHuber, "(0, 1000000]", "", "Huber loss on the prior residuals, whitened"},
      {"max_iterations", &o.maxIterations, "[1, 10000]", "", "Ceres iterations per solve"},
      {"odometry_translation_sigma_per_m", &o.odometryTranslationSigmaPerM, "(0, 10]", "m/m", "the built-in odometry's drift model per metre travelled, from which the estimate (x0.01 to x1000) starts"},
      {"odometry_rotation_sigma_deg_per_m", &o.odometryRotationSigmaDegPerM, "(0, 180]", "deg/m", "the same in rotation"},
      {"given_odometry_translation_sigma_per_m", &o.givenOdometryTranslationSigmaPerM, "(0, 10]", "m/m", "the same for a trajectory file (run --odometry)"},
      {"given_odometry_rotation_sigma_deg_per_m", &o.givenOdometryRotationSigmaDegPerM, "(0, 180]", "deg/m", "the same in rotation"},
      {"map_error_length", &o.mapErrorLength, "[0, 1000000]", "m", "the map's error is correlated along the route over this (0: independent per prior)"},
      {"drift_model_margin_nats", &o.driftModelMarginNats, "[0, 1000000]", "nats", "the final solve takes the tightest drift model this close to the likeliest"}};
}

}  // namespace hdprior
