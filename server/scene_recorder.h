// Records a match's scene track while it is played: into `<match>.scene` beside its replay,
// and/or to live viewers. Driven by the match's worker thread (MatchRuntime).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "live_scenes.h"
#include "replay.h"
#include "scene_track.h"

namespace olympics::server {

class SceneRecorder {
 public:
  // `file`: where the track goes ("" for none); `live`: null for none.
  SceneRecorder(std::string file, std::shared_ptr<LiveScene> live);
  void start(const sports::SportMatch& game, const std::string& sport, const nlohmann::json& about);
  void tick(const sports::SportMatch& game);
  // Writes the result and closes the file; returns its path ("" when none was written).
  std::string finish(const sports::SportMatch& game);

 private:
  std::string file_;
  std::optional<SceneFileWriter> writer_;
  std::shared_ptr<LiveScene> live_;
  SceneEncoder encoder_;
};

// What a track's header tells about its match, from a replay's header (or the same fields of a
// match being played): one choice of fields, so a track re-made from a replay is the recorded one.
nlohmann::json scene_about(const nlohmann::json& replay_header);

// Re-runs a replay to write its scene track at `path` (for replays recorded without one).
void record_scene_from_replay(const Replay& replay, const std::string& path);

}  // namespace olympics::server
