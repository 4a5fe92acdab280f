#include "engine/pipeline/run_summary.h"

#include "engine/pipeline/prior_constraint.h"
#include "engine/pipeline/session.h"

namespace hdprior {

RunSummary summarizeRun(const Session& session) {
  RunSummary s;
  const PoseTrajectory optimized = session.optimizedTrajectory();
  const PoseTrajectory trajectory = optimized.empty() ? session.odometryTrajectory() : optimized;
  s.ate = evaluateTrajectory(session.groundTruth(), trajectory, AlignmentMode::None).ate.translation;
  const std::vector<PriorConstraint> constraints = constraintsOf(session.matches());
  s.constraints = countConstraints(constraints);
  s.constraintSummary = constraintSummary(constraints);
  s.keyframes = session.odometry().keyframes().size();
  s.pipelineS = session.times().pipelineS;
  return s;
}

}  // namespace hdprior
