#include "ai/planner_evaluate.hpp"
#include "nineball/planner.hpp"

namespace nineball::ai {

// The Evaluator keeps references to the input and the table: both live here with it.
struct ShotValuer::Impl {
  explicit Impl(PlanInput position)
      : in(std::move(position)),
        table(buildTable(in.table, in.physics.ball_radius)),
        evaluator(in, table) {}

  PlanInput in;
  TableGeometry table;
  Evaluator evaluator;
};

ShotValuer::ShotValuer(PlanInput in) : impl_(std::make_unique<Impl>(std::move(in))) {}

ShotValuer::~ShotValuer() = default;

double ShotValuer::value(const Shot& shot) const {
  Candidate c;
  c.shot = shot;
  return impl_->evaluator.value(c);
}

}  // namespace nineball::ai
