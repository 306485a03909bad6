#include "sim/solver/baselines/make_baseline.h"

#include "sim/solver/baselines/follow_the_leader.h"
#include "sim/solver/baselines/mass_spring.h"
#include "sim/solver/baselines/pbd.h"

namespace csm {

std::unique_ptr<BaselineSolver> makeBaseline(std::string_view name, const BaselineParams& params) {
  if (name == "ms-explicit") return std::make_unique<ExplicitMassSpring>(params);
  if (name == "ms-implicit") return std::make_unique<ImplicitMassSpring>(params);
  if (name == "pbd") return std::make_unique<PbdSolver>(params);
  if (name == "ftl") return std::make_unique<FollowTheLeader>(params);
  return nullptr;
}

std::vector<std::string> baselineNames() {
  return {"ms-explicit", "ms-implicit", "pbd", "ftl"};
}

}  // namespace csm
