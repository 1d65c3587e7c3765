// The standing dribble's yardstick (issue 30): the scripted dribbler
// (scripted_basketball_dribble.h) takes the first check ball of a basketball 1v1 of each seed and
// dribbles it for `seconds`, the other slot the scripted team player standing as the defender. Per
// episode the consecutive dribbles before the ball was lost (DribbleTally, from the ball's true
// state), whether it was kept to the end, and whether the dribbler fell in the `seconds` (the
// episode runs them all, the ball lost or not). Summed: the median and 10th percentile of the
// dribbles, the episodes with one or more (Wilson 95%) and two or more, the share kept to the end
// (Wilson 95%), the episodes with a fall.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <vector>

namespace olympics::bench {

nlohmann::json scripted_dribbles(const std::vector<std::uint64_t>& seeds, double seconds,
                                 bool per_episode);

}  // namespace olympics::bench
