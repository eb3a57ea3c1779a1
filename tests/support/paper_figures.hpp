#pragma once

namespace nineball::testing {

/// The paper's printed answers (section 4) have two significant decimals at most: a figure
/// checked against them holds to half their last digit.
inline constexpr double kPrintedRounding = 0.005;

}  // namespace nineball::testing
