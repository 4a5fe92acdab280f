// What could any drivable-area matcher give under odometry drift? Runs LOG through the pipeline
// (config C, e.g. with odometry.drift), then rebuilds its pose graph (the same odometry factors and
// the drift model the run ended with) with other priors and prints each graph's keyframe ATE,
// split along and across the true heading:
//   matcher            the run's own priors (checks the rebuild against the run);
//   truth@matcher      the same keyframes, information and map sigma, the mean at the ground truth:
//                      a matcher without error but with today's observability;
//   J<sigma>:<bias>    the same, and where a prior observes the along-track place (a junction) an
//                      along sigma of SIGMA and an along error drawn from it (seeded, independent
//                      from fix to fix) plus BIAS: junction fixes of that quality;
//   lateral+yaw@all    a truth prior at every keyframe, lateral 0.1 m and yaw 0.2 deg, along free:
//                      the most a road's drivable area can say between junctions;
//   all@all            every keyframe, along 0.1 m too (the graph's floor).
// With SIGMA:BIAS arguments, J once for each (BIAS: a shared error of the fixes one junction gives, the
// matcher's are all ahead at the tuning logs' starting junction). Default: 0.2:0.
// PROBE_ODOMETRY_DIR=D takes the odometry from D/<log id>.tum, as `hdprior run --odometry` does.
//   probe_oracle_priors LOG CONFIG [SIGMA:BIAS ...]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "engine/error.h"
#include "engine/geom/se2.h"
#include "engine/graph/odometry_information.h"
#include "engine/io/argoverse_log.h"
#include "engine/odom/given_odometry.h"
#include "engine/pipeline/config.h"
#include "engine/pipeline/pipeline_run.h"

using namespace hdprior;

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The planar information with sigmas along and across heading yaw, in the prior's (yaw, x, y, z) order.
Eigen::Matrix4d headingInformation(double yaw, double sigmaAlong, double sigmaLateral, double sigmaYaw, double sigmaZ) {
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(yaw).toRotationMatrix();
  const Eigen::Vector2d inv(sigmaAlong > 0 ? 1.0 / (sigmaAlong * sigmaAlong) : 0.0, 1.0 / (sigmaLateral * sigmaLateral));
  Eigen::Matrix4d info = Eigen::Matrix4d::Zero();
  info(0, 0) = 1.0 / (sigmaYaw * sigmaYaw);
  info.block<2, 2>(1, 1) = R * inv.asDiagonal() * R.transpose();
  info(3, 3) = 1.0 / (sigmaZ * sigmaZ);
  return info;
}

// The prior's information along the heading yaw (metres^-2).
double alongInformation(const PosePrior& p, double yaw) {
  const Eigen::Vector2d a(std::cos(yaw), std::sin(yaw));
  return a.dot(p.information.block<2, 2>(1, 1) * a);
}

// A prior at keyframe k, or nothing.
using PriorOf = std::function<std::optional<PosePrior>(size_t k)>;

struct Ate {
  double rmse = 0, along = 0, lateral = 0, cost = 0;
  size_t priors = 0;
};

Ate keyframeAte(const std::vector<SE3>& poses, const std::vector<SE3>& truth) {
  Ate a;
  for (size_t k = 0; k < poses.size(); ++k) {
    const Eigen::Vector3d e = poses[k].translation() - truth[k].translation();
    const double yaw = yawOf(truth[k]);
    const double along = std::cos(yaw) * e.x() + std::sin(yaw) * e.y();
    const double lateral = -std::sin(yaw) * e.x() + std::cos(yaw) * e.y();
    a.rmse += e.squaredNorm();
    a.along += along * along;
    a.lateral += lateral * lateral;
  }
  const double n = double(std::max<size_t>(poses.size(), 1));
  a.rmse = std::sqrt(a.rmse / n);
  a.along = std::sqrt(a.along / n);
  a.lateral = std::sqrt(a.lateral / n);
  return a;
}

Ate solveWith(const PipelineRun& run, PoseGraphOptions options, const PriorOf& priorOf, const std::vector<SE3>& truth) {
  const std::vector<Keyframe>& keyframes = run.odometry->keyframes();
  PoseGraph graph(options);
  Ate a;
  for (size_t k = 0; k < keyframes.size(); ++k) {
    const Keyframe& kf = keyframes[k];
    graph.addKeyframe(kf.timestampNs, run.cityTOdom * kf.odomTEgo);
    if (k > 0) graph.addOdometry(k - 1, k, kf.previousTThis, odometryInformation(kf.relativeCovariance, kf.previousTThis, options));
    if (const std::optional<PosePrior> p = priorOf(k)) {
      graph.addPrior(k, *p);
      ++a.priors;
    }
  }
  const SolveSummary solved = graph.solve();
  const size_t priors = a.priors;
  a = keyframeAte(graph.poses(), truth);
  a.priors = priors;
  a.cost = solved.finalCost;
  return a;
}

}  // namespace

int main(int argc, char** argv) try {
  if (argc < 3) {
    std::fprintf(stderr, "usage: probe_oracle_priors LOG CONFIG [SIGMA:BIAS ...]\n");
    return 2;
  }
  std::vector<std::pair<double, double>> junctionFixes;
  for (int i = 3; i < argc; ++i) {
    double sigma = 0, bias = 0;
    if (std::sscanf(argv[i], "%lf:%lf", &sigma, &bias) != 2 || !(sigma > 0)) {
      std::fprintf(stderr, "probe_oracle_priors: '%s' is not SIGMA:BIAS\n", argv[i]);
      return 2;
    }
    junctionFixes.emplace_back(sigma, bias);
  }
  if (junctionFixes.empty()) junctionFixes.emplace_back(0.2, 0.0);
  const ArgoverseLog log(argv[1]);
  const Config config = loadConfig(argv[2]);
  PipelineOptions pipeline;
  if (const char* dir = std::getenv("PROBE_ODOMETRY_DIR")) {
    pipeline.givenOdometry = givenOdometryOf(std::filesystem::path(dir) / (log.id() + ".tum"), {}, log);
  }
  const PipelineRun run = runPipeline(log, config, pipeline);
  const std::vector<Keyframe>& keyframes = run.odometry->keyframes();
  std::vector<SE3> truth, odometry;
  for (const Keyframe& kf : keyframes) {
    truth.push_back(run.groundTruth.at(kf.timestampNs));
    odometry.push_back(run.cityTOdom * kf.odomTEgo);
  }
  const auto truthPrior = [&](size_t k, const Eigen::Matrix4d& information, double mapSigma) {
    PosePrior p;
    p.pose = truth[k];
    p.information = information;
    p.mapSigma = mapSigma;
    return p;
  };
  const auto matcherPrior = [&](size_t k) -> std::optional<PosePrior> {
    const KeyframeMatch& m = run.matches.at(k);
    if (!m.hasPrior) return std::nullopt;
    return m.prior;
  };
  const auto truthAtMatcher = [&](size_t k) -> std::optional<PosePrior> {
    const KeyframeMatch& m = run.matches.at(k);
    if (!m.hasPrior) return std::nullopt;
    return truthPrior(k, m.prior.information, m.prior.mapSigma);
  };
  const auto truthAtMatcherJunctions = [&](size_t k, double junctionAlongSigma, double junctionBias) -> std::optional<PosePrior> {
    std::optional<PosePrior> p = truthAtMatcher(k);
    const double yaw = yawOf(truth[k]);
    if (!p || alongInformation(*p, yaw) < 1.0 / 9.0) return p;  // along sigma over 3 m: not a junction fix
    const Eigen::Vector2d a(std::cos(yaw), std::sin(yaw));
    Eigen::Matrix4d info = p->information;
    info.block<2, 2>(1, 1) += (1.0 / (junctionAlongSigma * junctionAlongSigma) - alongInformation(*p, yaw)) * a * a.transpose();
    p->information = info;
    std::mt19937 random(unsigned(k) * 7919u + 17u);
    std::normal_distribution<double> error(junctionBias, junctionAlongSigma);
    p->pose.translation().head<2>() += error(random) * a;
    return p;
  };
  const auto lateralYawAll = [&](size_t k) -> std::optional<PosePrior> {
    return truthPrior(k, headingInformation(yawOf(truth[k]), 0.0, 0.1, 0.2 * kDeg, 0.1), 0.0);
  };
  const auto allAll = [&](size_t k) -> std::optional<PosePrior> {
    return truthPrior(k, headingInformation(yawOf(truth[k]), 0.1, 0.1, 0.2 * kDeg, 0.1), 0.0);
  };

  const Ate odo = keyframeAte(odometry, truth);
  const Ate opt = keyframeAte(run.optimizedKeyframes, truth);
  std::printf("log %s keyframes %zu\n", log.id().c_str(), keyframes.size());
  std::printf("%-18s %6s %8s %8s %8s\n", "priors", "count", "ate", "along", "lateral");
  std::printf("%-18s %6s %8.3f %8.3f %8.3f\n", "odometry", "-", odo.rmse, odo.along, odo.lateral);
  std::printf("%-18s %6s %8.3f %8.3f %8.3f\n", "run", "-", opt.rmse, opt.along, opt.lateral);
  std::vector<std::pair<std::string, PriorOf>> variants = {{"matcher", matcherPrior}, {"truth@matcher", truthAtMatcher}};
  for (const auto& [sigma, bias] : junctionFixes) {
    char name[64];
    std::snprintf(name, sizeof name, "J%.2g:%.2g", sigma, bias);
    variants.emplace_back(name, [&, sigma, bias](size_t k) { return truthAtMatcherJunctions(k, sigma, bias); });
  }
  variants.emplace_back("lateral+yaw@all", lateralYawAll);
  variants.emplace_back("all@all", allAll);
  for (const auto& [name, priorOf] : variants) {
    const Ate a = solveWith(run, run.graphOptions, priorOf, truth);
    std::printf("%-18s %6zu %8.3f %8.3f %8.3f", name.c_str(), a.priors, a.rmse, a.along, a.lateral);
    if (std::getenv("PROBE_COST")) std::printf("  cost %.2f", a.cost);
    std::printf("\n");
  }
  return 0;
} catch (const hdprior::Error& e) {
  std::fprintf(stderr, "probe_oracle_priors: %s\n", e.what());
  return 2;
}
