#include "scene_recorder.h"

namespace olympics::server {

SceneRecorder::SceneRecorder(std::string file, std::shared_ptr<LiveScene> live)
    : file_(std::move(file)), live_(std::move(live)) {}

void SceneRecorder::start(const sports::SportMatch& game, const std::string& sport,
                          const nlohmann::json& about) {
  std::string records = encoder_.header(game, sport, about);
  if (!file_.empty()) writer_.emplace(file_);
  if (writer_) writer_->write(records);
  if (live_) live_->publish_header(records);
  tick(game);  // the start position
}

void SceneRecorder::tick(const sports::SportMatch& game) {
  std::string records = encoder_.frame(game);
  if (writer_) writer_->write(records);
  if (live_) live_->publish_tick(game.tick(), std::move(records));
}

std::string SceneRecorder::finish(const sports::SportMatch& game) {
  std::string records = encoder_.result(game);
  std::string path;
  if (writer_) {
    writer_->write(records);
    path = writer_->close();
    writer_.reset();
  }
  if (live_) live_->end(std::move(records));
  return path;
}

nlohmann::json scene_about(const nlohmann::json& h) {
  return {{"match_id", h.value("match_id", "")},
          {"server_id", h.value("server_id", "")},
          {"mode", h.at("mode")},
          {"seed", h.at("seed")},
          {"options", h.value("options", nlohmann::json::object())},
          {"realtime", h.value("realtime", false)},
          {"agents", h.value("agents", nlohmann::json::array())}};
}

void record_scene_from_replay(const Replay& replay, const std::string& path) {
  SceneRecorder recorder(path, nullptr);
  const auto& h = replay.header;
  const nlohmann::json about = scene_about(h);
  bool started = false;
  auto match = rerun_replay(replay, [&](const sports::SportMatch& game) {
    if (!started) {
      recorder.start(game, h.at("sport"), about);
      started = true;
    } else {
      recorder.tick(game);
    }
  });
  recorder.finish(*match);
}

}  // namespace olympics::server
