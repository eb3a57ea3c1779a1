#include "fit/calibration_stats.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "fit/physics_scorer.hpp"
#include "nineball/random.hpp"

namespace nineball::fit {
namespace {

using Vector = std::vector<double>;
using Resample = std::vector<std::size_t>;

// More resamples than this share whose best physics ties in a parameter, or lies at the edge of
// its values tried, leave the parameter undetermined.
constexpr double kMostUndetermined = 0.1;
// A spread this small, as a share of a parameter's typical step, is rounding: every resample had
// the same best physics.
constexpr double kRounding = 1e-9;

std::vector<Resample> resamplesOf(std::size_t shots, int count, std::uint64_t seed) {
  std::vector<Resample> out(static_cast<std::size_t>(std::max(count, 0)), Resample(shots));
  std::uint64_t state = seed;
  for (Resample& r : out) {
    for (std::size_t& i : r) i = splitmix64(state) % shots;
  }
  return out;
}

double resampledMedian(const ScoredPhysics& s, const Resample& r) {
  Vector errors;
  errors.reserve(r.size());
  for (std::size_t i : r) errors.push_back(s.errors[i]);
  return median(errors);
}

// The physics tried whose median over the resample is the least (the first tried of equals).
const ScoredPhysics* bestUnder(const std::vector<const ScoredPhysics*>& scored, const Resample& r) {
  const ScoredPhysics* best = scored.front();
  double least = std::numeric_limits<double>::infinity();
  for (const ScoredPhysics* s : scored) {
    const double m = resampledMedian(*s, r);
    if (m < least) {
      least = m;
      best = s;
    }
  }
  return best;
}

// How the resamples' best physics fall in one parameter.
struct Tally {
  std::size_t tied = 0;     // resamples whose best physics has a twin that differs in it
  std::size_t at_edge = 0;  // resamples whose best lies at the least or most value tried
};

class Bootstrap {
 public:
  explicit Bootstrap(const BootstrapInput& in) : in_(in), p_(in.best.size()) {
    for (const ScoredPhysics& s : in.tried) {
      if (std::isfinite(s.median) && !s.errors.empty()) scored_.push_back(&s);
    }
    least_.assign(p_, std::numeric_limits<double>::infinity());
    most_.assign(p_, -std::numeric_limits<double>::infinity());
    for (const ScoredPhysics* s : scored_) {
      for (std::size_t k = 0; k < p_; ++k) {
        least_[k] = std::min(least_[k], s->values[k]);
        most_[k] = std::max(most_[k], s->values[k]);
      }
    }
  }

  std::size_t shots() const { return scored_.empty() ? 0 : scored_.front()->errors.size(); }
  std::size_t scored() const { return scored_.size(); }

  void run(const std::vector<Resample>& resamples, CalibrationUncertainty& out) {
    std::vector<Tally> tallies(p_);
    std::vector<Vector> best;
    for (const Resample& r : resamples) {
      const ScoredPhysics* b = bestUnder(scored_, r);
      const Vector& v = b->values;
      for (std::size_t k = 0; k < p_; ++k) {
        tallies[k].tied += hasTwinApartIn(*b, k);
        tallies[k].at_edge += least_[k] < most_[k] && (v[k] == least_[k] || v[k] == most_[k]);
      }
      best.push_back(v);
    }
    spreadOf(best, determined(tallies, resamples.size()), out);
    out.why_not = joined(reasons_);
  }

 private:
  // Whether another physics tried gives every shot exactly the same error but differs in
  // parameter k: the shots cannot tell its values apart there.
  bool hasTwinApartIn(const ScoredPhysics& s, std::size_t k) const {
    return std::any_of(scored_.begin(), scored_.end(), [&](const ScoredPhysics* other) {
      return other->values[k] != s.values[k] && other->errors == s.errors;
    });
  }

  // The parameters whose resamples' best physics neither tie nor lie at the edge too often.
  std::vector<std::size_t> determined(const std::vector<Tally>& tallies, std::size_t resamples) {
    const double most = kMostUndetermined * static_cast<double>(resamples);
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < p_; ++k) {
      const std::string of = " of " + std::to_string(resamples) + " resamples";
      if (static_cast<double>(tallies[k].tied) > most) {
        reasons_.push_back(in_.names[k] + ": the median does not tell its values apart (ties in " +
                           std::to_string(tallies[k].tied) + of + ")");
      } else if (static_cast<double>(tallies[k].at_edge) > most) {
        reasons_.push_back(in_.names[k] + ": the best physics lies at the edge of the values " +
                           "tried in " + std::to_string(tallies[k].at_edge) + of);
      } else {
        out.push_back(k);
      }
    }
    return out;
  }

  // The standard deviations and correlations of the resamples' best values in `parameters`.
  void spreadOf(const std::vector<Vector>& best, const std::vector<std::size_t>& parameters,
                CalibrationUncertainty& out) {
    const double n = static_cast<double>(best.size());
    Vector mean(p_, 0.0);
    for (const Vector& b : best) {
      for (std::size_t k : parameters) mean[k] += b[k] / n;
    }
    std::vector<Vector> cov(p_, Vector(p_, 0.0));
    for (const Vector& b : best) {
      for (std::size_t j : parameters) {
        for (std::size_t k : parameters) cov[j][k] += (b[j] - mean[j]) * (b[k] - mean[k]) / (n - 1);
      }
    }
    std::vector<std::size_t> spread;
    for (std::size_t k : parameters) {
      if (std::sqrt(cov[k][k]) > kRounding * in_.scale[k] && std::isfinite(cov[k][k])) {
        out.stderrs[k] = std::sqrt(cov[k][k]);
        spread.push_back(k);
      } else {
        reasons_.push_back(in_.names[k] +
                           ": the same physics was best in every resample (an uncertainty "
                           "below the spacing of the physics tried)");
      }
    }
    for (std::size_t j : spread) {
      for (std::size_t k : spread) {
        if (j != k) out.correlation[j][k] = cov[j][k] / (*out.stderrs[j] * *out.stderrs[k]);
      }
    }
  }

  static std::string joined(const std::vector<std::string>& parts) {
    std::string out;
    for (const std::string& p : parts) out += (out.empty() ? "" : "; ") + p;
    return out;
  }

  const BootstrapInput& in_;
  std::size_t p_;
  std::vector<const ScoredPhysics*> scored_;
  Vector least_, most_;
  std::vector<std::string> reasons_;
};

CalibrationUncertainty undetermined(const BootstrapInput& in) {
  const std::size_t p = in.best.size();
  CalibrationUncertainty out;
  out.resamples = in.resamples;
  out.stderrs.assign(p, std::nullopt);
  out.correlation.assign(p, std::vector<std::optional<double>>(p));
  for (std::size_t k = 0; k < p; ++k) out.correlation[k][k] = 1.0;
  return out;
}

}  // namespace

CalibrationUncertainty bootstrapOverShots(const BootstrapInput& in) {
  CalibrationUncertainty out = undetermined(in);
  Bootstrap bootstrap(in);
  if (bootstrap.shots() < 2) {
    out.why_not = "fewer than 2 training shots: nothing to resample";
  } else if (bootstrap.scored() < 2) {
    out.why_not = "fewer than 2 physics scored: nothing to choose between";
  } else if (in.resamples < 2) {
    out.why_not = "fewer than 2 resamples";
  } else {
    bootstrap.run(resamplesOf(bootstrap.shots(), in.resamples, in.seed), out);
  }
  return out;
}

}  // namespace nineball::fit
