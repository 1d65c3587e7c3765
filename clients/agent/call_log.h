// olympics-agent --calls: the referee's decisions and the score as they happen, read from each
// observation's info (so any agent of a match can follow it live). Which calls are decisions
// people follow is the sport's own word: its description flags them `announced`
// (sports/sport.h), so a new sport's calls print without a list here.
#pragma once

#include <optional>
#include <set>
#include <string>
#include <vector>

namespace olympics::client {

// The calls that `sport`'s description announces in `mode`; nullopt when this build does not
// know the sport or the mode (a newer server): then every call is shown.
std::optional<std::set<std::string>> announced_calls(const std::string& sport,
                                                     const std::string& mode);

// One line per announced call in an observation's info ("tick 197: point to team 0 (touch)
// 1-0"); none when the info holds no events or is of another shape than the referee writes.
std::vector<std::string> call_lines(int tick, const std::string& info,
                                    const std::optional<std::set<std::string>>& announced);

}  // namespace olympics::client
