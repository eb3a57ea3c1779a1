#include "fit/physics_scorer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

#include "common/parallel_map.hpp"

namespace nineball::fit {

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string valuesText(const std::vector<double>& values) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    char text[32];
    const auto end = std::to_chars(text, text + sizeof text, values[i]).ptr;
    out += (i ? ", " : "") + std::string(text, end);
  }
  return out;
}

std::vector<Found> refitAll(const std::vector<const RecordedShot*>& shots, const PhysicsParams& p,
                            const std::vector<Found>& from, int evals, int threads,
                            const std::atomic<bool>* cancel) {
  std::vector<Found> out(shots.size());
  parallelFor(shots.size(), threads, [&](std::size_t k) {
    out[k] = refineShot(*shots[k], p, from[k].x, evals, FitObjective::Full, cancel);
  });
  return out;
}

PhysicsScorer::PhysicsScorer(std::vector<const RecordedShot*> shots, std::vector<Found> anchors,
                             Settings settings)
    : shots_(std::move(shots)), anchors_(std::move(anchors)), settings_(std::move(settings)) {}

namespace {

bool allFinite(const std::vector<double>& values) {
  return std::all_of(values.begin(), values.end(), [](double v) { return std::isfinite(v); });
}

}  // namespace

const PhysicsScorer::Entry& PhysicsScorer::entryOf(const std::vector<double>& values) {
  if (const auto known = index_.find(values); known != index_.end()) {
    return entries_[known->second];
  }
  Entry e;
  e.scored.values = values;
  e.scored.median = std::numeric_limits<double>::infinity();
  std::string why;
  const std::optional<PhysicsParams> p =
      allFinite(values) ? settings_.set(settings_.base, values, why) : std::nullopt;
  if (p) {
    e.refits =
        refitAll(shots_, *p, anchors_, settings_.refit_evals, settings_.threads, settings_.cancel);
    for (const Found& f : e.refits) e.scored.errors.push_back(f.error);
    e.scored.median = median(e.scored.errors);
  }
  // A value that is not a number has no place in the index's order; it is refused anyway.
  if (allFinite(values)) index_[values] = entries_.size();
  entries_.push_back(std::move(e));
  return entries_.back();
}

bool PhysicsScorer::scored(const std::vector<double>& values) const {
  return index_.count(values) > 0;
}

std::size_t PhysicsScorer::numberOf(const std::vector<double>& values) const {
  const auto known = index_.find(values);
  return known == index_.end() ? 0 : known->second + 1;
}

const ScoredPhysics& PhysicsScorer::score(const std::vector<double>& values) {
  return entryOf(values).scored;
}

const std::vector<Found>& PhysicsScorer::refitsOf(const std::vector<double>& values) {
  return entryOf(values).refits;
}

std::vector<ScoredPhysics> PhysicsScorer::tried() const {
  std::vector<ScoredPhysics> out;
  for (const Entry& e : entries_) out.push_back(e.scored);
  return out;
}

}  // namespace nineball::fit
