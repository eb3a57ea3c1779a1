#include "net/rack_allowance.hpp"

namespace nineball::net {

RackAllowance::RackAllowance(int most_heals, int most_rejoins)
    : most_heals_(most_heals), most_rejoins_(most_rejoins) {}

bool RackAllowance::takeRejoin() {
  ++rejoins_;
  return rejoins_ <= most_rejoins_;
}

}  // namespace nineball::net
