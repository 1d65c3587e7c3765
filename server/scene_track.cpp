#include "scene_track.h"

#include <zstd.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace olympics::server {
namespace {

template <typename T>
void put(std::string& out, T v) {
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  out.append(b, sizeof(T));
}

template <typename T>
T get(std::string_view in, size_t& at) {
  if (at + sizeof(T) > in.size()) throw std::runtime_error("scene track: a record is cut short");
  T v;
  std::memcpy(&v, in.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

std::int16_t quantise(double v, double scale) {
  return static_cast<std::int16_t>(std::lround(std::clamp(v * scale, -32767.0, 32767.0)));
}

}  // namespace

void append_record(std::string& out, char type, std::string_view payload) {
  out.push_back(type);
  put(out, static_cast<std::uint32_t>(payload.size()));
  out.append(payload);
}

std::string SceneEncoder::header(const sports::SportMatch& game, const std::string& sport,
                                 const nlohmann::json& about) {
  nlohmann::json scene = game.scene_description();
  game.scene_poses(poses_);
  nlohmann::json h = about;
  h["format"] = "olympics-scene";
  h["version"] = 1;
  h["sport"] = sport;
  h["control_hz"] = game.control_hz();
  h["slots"] = game.slot_count();
  h["team_count"] = game.team_count();
  h["reward_terms"] = game.reward_terms();
  h["body_count"] = poses_.size() / 7;
  h["position_quantum_m"] = kScenePositionQuantum;
  h["time_limit_s"] = game.time_limit_s();
  h["scene"] = scene.is_null() ? nlohmann::json::object() : scene;
  std::string out;
  append_record(out, 'H', h.dump());
  return out;
}

std::string SceneEncoder::frame(const sports::SportMatch& game) {
  game.scene_poses(poses_);
  const auto& o = game.outcome();
  frame_.clear();
  put(frame_, static_cast<std::uint32_t>(game.tick()));
  for (size_t b = 0; b + 7 <= poses_.size(); b += 7) {
    for (int i = 0; i < 3; ++i) put(frame_, quantise(poses_[b + i], 1 / kScenePositionQuantum));
    for (int i = 3; i < 7; ++i) put(frame_, quantise(poses_[b + i], 32767.0));
  }
  for (int t = 0; t < game.team_count(); ++t)
    put(frame_, t < static_cast<int>(o.scores.size()) ? o.scores[t] : 0.0f);
  const size_t terms = game.reward_terms().size();
  for (int s = 0; s < game.slot_count(); ++s) {
    const bool have = s < static_cast<int>(o.reward.size());
    put(frame_, have ? o.reward[s] : 0.0f);
    for (size_t k = 0; k < terms; ++k)
      put(frame_, have && k < o.terms[s].size() ? o.terms[s][k] : 0.0f);
  }
  std::string out;
  append_record(out, 'F', frame_);
  const auto events = o.info.find("events");
  const bool called = events != o.info.end() && !events->empty();
  const auto score = o.info.find("score");
  const bool has_score = score != o.info.end();
  // Compared as JSON: no text is made for a tick whose score did not change.
  const bool score_changed = has_score ? *score != last_score_ : !last_score_.is_null();
  if (called || score_changed) {
    nlohmann::json e = {{"tick", game.tick()},
                        {"events", called ? *events : nlohmann::json::array()}};
    if (has_score) e["score"] = *score;
    append_record(out, 'E', e.dump());
    last_score_ = has_score ? *score : nlohmann::json();
  }
  return out;
}

std::string SceneEncoder::result(const sports::SportMatch& game) {
  const auto& o = game.outcome();
  nlohmann::json r = {{"reason", o.reason},
                      {"winner_team", o.winner_team},
                      {"scores", o.scores},
                      {"ticks", game.tick()},
                      {"info", o.info}};
  std::string out;
  append_record(out, 'R', r.dump());
  return out;
}

SceneFileWriter::SceneFileWriter(std::string path)
    : path_(std::move(path)), part_(path_ + ".part"), out_(ZSTD_CStreamOutSize()) {
  file_ = std::fopen(part_.c_str(), "wb");
  if (!file_) throw std::runtime_error("cannot write the scene track " + part_);
  zstd_ = ZSTD_createCCtx();
  ZSTD_CCtx_setParameter(zstd_, ZSTD_c_compressionLevel, 3);
  ZSTD_CCtx_setParameter(zstd_, ZSTD_c_checksumFlag, 1);
}

SceneFileWriter::~SceneFileWriter() {
  if (file_) {
    std::fclose(file_);
    std::remove(part_.c_str());  // never closed: an unfinished track is not kept
  }
  ZSTD_freeCCtx(zstd_);
}

void SceneFileWriter::drive(std::string_view in, int mode) {
  ZSTD_inBuffer input{in.data(), in.size(), 0};
  const auto end_op = static_cast<ZSTD_EndDirective>(mode);
  for (;;) {
    ZSTD_outBuffer output{out_.data(), out_.size(), 0};
    const size_t left = ZSTD_compressStream2(zstd_, &output, &input, end_op);
    if (ZSTD_isError(left))
      throw std::runtime_error("scene track " + part_ + ": " + ZSTD_getErrorName(left));
    if (output.pos && std::fwrite(out_.data(), 1, output.pos, file_) != output.pos)
      throw std::runtime_error("scene track " + part_ + ": write failed (disk full?)");
    const bool done = end_op == ZSTD_e_end ? left == 0 : input.pos == input.size;
    if (done) return;
  }
}

void SceneFileWriter::write(std::string_view records) { drive(records, ZSTD_e_continue); }

std::string SceneFileWriter::close() {
  drive({}, ZSTD_e_end);
  const bool ok = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok) throw std::runtime_error("scene track " + part_ + ": close failed");
  std::filesystem::rename(part_, path_);
  return path_;
}

std::string read_packed_scene_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read the scene track " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string read_scene_file(const std::string& path) {
  return unpack_scene(read_packed_scene_file(path), path);
}

std::string unpack_scene(std::string_view packed, const std::string& path) {
  ZSTD_DCtx* z = ZSTD_createDCtx();
  std::string out;
  std::vector<char> buf(ZSTD_DStreamOutSize());
  ZSTD_inBuffer input{packed.data(), packed.size(), 0};
  size_t last = 0;
  while (input.pos < input.size) {
    ZSTD_outBuffer output{buf.data(), buf.size(), 0};
    last = ZSTD_decompressStream(z, &output, &input);
    if (ZSTD_isError(last)) {
      const std::string why = ZSTD_getErrorName(last);
      ZSTD_freeDCtx(z);
      throw std::runtime_error(path + " is not a scene track (zstd: " + why + ")");
    }
    out.append(buf.data(), output.pos);
  }
  ZSTD_freeDCtx(z);
  if (last != 0) throw std::runtime_error(path + ": the scene track is cut short");
  return out;
}

SceneTrack decode_scene(std::string_view records) {
  SceneTrack t;
  size_t at = 0;
  int bodies = 0, teams = 0, per_slot = 0, slots = 0;
  while (at < records.size()) {
    const char type = get<char>(records, at);
    const auto size = get<std::uint32_t>(records, at);
    if (at + size > records.size()) throw std::runtime_error("scene track: a record is cut short");
    const std::string_view body = records.substr(at, size);
    at += size;
    if (type == 'H') {
      t.header = nlohmann::json::parse(body);
      bodies = t.header.at("body_count");
      teams = t.header.at("team_count");
      slots = t.header.at("slots");
      per_slot = 1 + static_cast<int>(t.header.at("reward_terms").size());
    } else if (type == 'F') {
      if (t.header.is_null()) throw std::runtime_error("scene track: a frame before the header");
      SceneTrack::Frame f;
      size_t p = 0;
      f.tick = static_cast<int>(get<std::uint32_t>(body, p));
      for (int b = 0; b < bodies; ++b) {
        for (int i = 0; i < 3; ++i)
          f.poses.push_back(get<std::int16_t>(body, p) * static_cast<float>(kScenePositionQuantum));
        for (int i = 0; i < 4; ++i) f.poses.push_back(get<std::int16_t>(body, p) / 32767.0f);
      }
      for (int k = 0; k < teams; ++k) f.scores.push_back(get<float>(body, p));
      for (int k = 0; k < slots * per_slot; ++k) f.rewards.push_back(get<float>(body, p));
      t.frames.push_back(std::move(f));
    } else if (type == 'E') {
      t.events.push_back(nlohmann::json::parse(body));
    } else if (type == 'R') {
      t.result = nlohmann::json::parse(body);
    }
  }
  return t;
}

}  // namespace olympics::server
