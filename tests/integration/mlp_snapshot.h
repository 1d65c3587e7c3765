// A small MLP snapshot file for the league's self-play tests (one host and the fleet).
#pragma once

#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace olympics::testing {

// A one-layer MLP snapshot (366 -> 69, tanh output) with small deterministic weights.
inline void write_snapshot(const std::string& path, int version) {
  const int in = 366, out = 69;
  std::vector<float> w(in * out), b(out, 0.0f);
  std::uint32_t state = 12345u * static_cast<std::uint32_t>(version);
  for (auto& x : w)
    state = state * 1664525u + 1013904223u, x = ((state >> 8) % 2001 - 1000) * 1e-4f;
  nlohmann::json header = {
      {"__metadata__", {{"format", "olympics-mlp"}, {"output", "tanh"}}},
      {"layers.0.weight",
       {{"dtype", "F32"}, {"shape", {out, in}}, {"data_offsets", {0, w.size() * 4}}}},
      {"layers.0.bias",
       {{"dtype", "F32"},
        {"shape", {out}},
        {"data_offsets", {w.size() * 4, (w.size() + b.size()) * 4}}}}};
  std::string text = header.dump();
  text.append((8 - text.size() % 8) % 8, ' ');
  std::ofstream f(path, std::ios::binary);
  std::uint64_t n = text.size();
  f.write(reinterpret_cast<const char*>(&n), 8);
  f << text;
  f.write(reinterpret_cast<const char*>(w.data()), static_cast<std::streamsize>(w.size() * 4));
  f.write(reinterpret_cast<const char*>(b.data()), static_cast<std::streamsize>(b.size() * 4));
}

}  // namespace olympics::testing
