// The scene track: what a match looked like, for viewers. Derived data: the replay (actions and
// seed) is what re-runs a match; the scene track only records where every body was.
//
// A track is a sequence of records, each `type (1 byte) | length (u32, little-endian) | payload`,
// so a reader skips types it does not know:
//   'H' header, JSON: format, version, match, sport, mode, seed, control_hz, teams, agents,
//       reward_terms, body_count, position_quantum_m and the sport's scene (scene_view.h)
//   'F' frame: tick (u32), then per body position (3 x int16, millimetres, clamped to +-32.767 m)
//       and orientation (4 x int16, quaternion w x y z times 32767), then the teams' scores
//       (float32 each), then per slot its reward and its reward terms (float32 each)
//   'E' referee events of the frame before it, JSON {tick, events, score}: written when the tick
//       made a call or the sport's score changed
//   'R' result, JSON {reason, winner_team, scores, ticks, info}
// On disk (`<match>.scene` beside the replay) the records are one zstd stream; live viewers get
// the records one by one (docs/viewer.md).
#pragma once

#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "sport.h"

struct ZSTD_CCtx_s;

namespace olympics::server {

inline constexpr double kScenePositionQuantum = 0.001;  // m per int16 step

void append_record(std::string& out, char type, std::string_view payload);

// Turns a match into records, tick by tick.
class SceneEncoder {
 public:
  // `about`: match id, agents and whatever else the viewer should show.
  std::string header(const sports::SportMatch& game, const std::string& sport,
                     const nlohmann::json& about);
  // The frame of the game's current tick, then its events record if it has one.
  std::string frame(const sports::SportMatch& game);
  std::string result(const sports::SportMatch& game);

 private:
  std::vector<float> poses_;
  std::string frame_;
  nlohmann::json last_score_;  // null: the sport keeps no score (or none yet)
};

// Writes records to `<path>.part` through zstd and renames it to `path` when closed, so a
// crash never leaves a truncated track under the final name.
class SceneFileWriter {
 public:
  explicit SceneFileWriter(std::string path);
  ~SceneFileWriter();
  SceneFileWriter(const SceneFileWriter&) = delete;
  SceneFileWriter& operator=(const SceneFileWriter&) = delete;
  void write(std::string_view records);
  // Ends the zstd stream and gives the file its name; returns the path.
  std::string close();

 private:
  void drive(std::string_view in, int mode);
  std::string path_, part_;
  std::FILE* file_ = nullptr;
  ZSTD_CCtx_s* zstd_ = nullptr;
  std::vector<char> out_;
};

// A decoded track (tests, `olympics-server view`'s summary).
struct SceneTrack {
  struct Frame {
    int tick = 0;
    std::vector<float> poses;  // 7 per body, dequantised
    std::vector<float> scores;
    std::vector<float> rewards;  // per slot: reward then terms
  };
  nlohmann::json header;
  std::vector<Frame> frames;
  nlohmann::json events = nlohmann::json::array();
  nlohmann::json result;
};
// Throws std::runtime_error naming what is wrong.
std::string read_scene_file(const std::string& path);  // the decompressed records
// A scene track's file as it is on disk (compressed), and its records decompressed (`name` for
// errors).
std::string read_packed_scene_file(const std::string& path);
std::string unpack_scene(std::string_view packed, const std::string& name);
SceneTrack decode_scene(std::string_view records);

}  // namespace olympics::server
