#include "call_log.h"

#include <nlohmann/json.hpp>
#include <stdexcept>

#include "registry.h"

namespace olympics::client {

std::optional<std::set<std::string>> announced_calls(const std::string& sport,
                                                     const std::string& mode) {
  const sports::Sport* s = sports::find_sport(sport);
  if (!s) return std::nullopt;
  try {
    std::set<std::string> names;
    for (const auto& call : s->layout(mode).calls)
      if (call.announced) names.insert(call.name);
    return names;
  } catch (const std::invalid_argument&) {
    return std::nullopt;  // a mode this build does not know
  }
}

std::vector<std::string> call_lines(int tick, const std::string& info_text,
                                    const std::optional<std::set<std::string>>& announced) {
  std::vector<std::string> lines;
  if (info_text.empty()) return lines;
  try {
    const auto info = nlohmann::json::parse(info_text, nullptr, false);
    if (!info.is_object() || !info.contains("events")) return lines;
    const std::string score = info.contains("score") ? info["score"].value("text", "") : "";
    for (const auto& e : info["events"]) {
      const std::string call = e.value("call", "");
      if (announced && !announced->count(call)) continue;
      std::string line = "tick " + std::to_string(tick) + ": " + call;
      if (e.contains("winner_team"))
        line += " to team " + std::to_string(e["winner_team"].get<int>());
      else if (e.contains("slot"))
        line += " slot " + std::to_string(e["slot"].get<int>());
      if (e.contains("round")) line += " round " + std::to_string(e["round"].get<int>());
      if (e.contains("team") && !e.contains("slot"))
        line += " team " + std::to_string(e["team"].get<int>());
      for (const char* what : {"reason", "kind", "line"})
        if (e.contains(what)) line += " (" + e[what].get<std::string>() + ")";
      if (e.contains("strokes")) {
        const int strokes = e["strokes"].get<int>();
        line += " after " + std::to_string(strokes) + (strokes == 1 ? " stroke" : " strokes");
      }
      if (e.contains("card_0"))
        line += " card " + std::to_string(e["card_0"].get<int>()) + "-" +
                std::to_string(e["card_1"].get<int>());
      lines.push_back(line + "  " + score);
    }
  } catch (const nlohmann::json::exception&) {
    // Info of another shape than the referee writes: nothing more to print.
  }
  return lines;
}

}  // namespace olympics::client
