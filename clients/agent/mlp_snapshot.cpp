#include "mlp_snapshot.h"

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace olympics::client {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

// The float32 tensor `name` with the given shape (one or two dimensions), from the file's bytes.
std::vector<float> tensor(const std::string& path, const nlohmann::json& header,
                          const std::string& bytes, const std::string& name,
                          std::vector<long> shape) {
  if (!header.contains(name)) fail(path, "no tensor \"" + name + "\"");
  const auto& t = header[name];
  if (t.value("dtype", "") != "F32")
    fail(path, "tensor \"" + name + "\" is " + t.value("dtype", "?") + ", not F32");
  const auto got = t.at("shape").get<std::vector<long>>();
  if (got != shape)
    fail(path, "tensor \"" + name + "\" has shape " + t.at("shape").dump() + ", expected " +
                   nlohmann::json(shape).dump());
  const auto offsets = t.at("data_offsets").get<std::vector<size_t>>();
  size_t count = 1;
  for (long d : shape) count *= static_cast<size_t>(d);
  if (offsets.size() != 2 || offsets[1] < offsets[0] || offsets[1] > bytes.size() ||
      offsets[1] - offsets[0] != count * sizeof(float))
    fail(path, "tensor \"" + name + "\" has data offsets outside the file or of the wrong size");
  std::vector<float> out(count);
  std::memcpy(out.data(), bytes.data() + offsets[0], count * sizeof(float));
  for (float v : out)
    if (!std::isfinite(v)) fail(path, "tensor \"" + name + "\" holds NaN or Inf");
  return out;
}

}  // namespace

MlpSnapshot MlpSnapshot::load(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, "cannot open the snapshot");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string file = buffer.str();
  if (file.size() < 8) fail(path, "too short to be a safetensors file");
  std::uint64_t header_size = 0;
  for (int i = 7; i >= 0; --i)
    header_size = (header_size << 8) | static_cast<unsigned char>(file[i]);
  if (header_size > file.size() - 8)
    fail(path, "the header length points past the end: not a safetensors file?");
  nlohmann::json header;
  try {
    header = nlohmann::json::parse(file.substr(8, header_size));
  } catch (const nlohmann::json::exception& e) {
    fail(path, std::string("the header is not JSON: ") + e.what());
  }
  const std::string bytes = file.substr(8 + header_size);

  MlpSnapshot s;
  s.path_ = path;
  if (header.contains("__metadata__"))
    for (auto& [k, v] : header["__metadata__"].items())
      s.metadata_[k] = v.is_string() ? v.get<std::string>() : v.dump();
  auto meta = [&](const std::string& key, const std::string& fallback) {
    auto it = s.metadata_.find(key);
    return it == s.metadata_.end() ? fallback : it->second;
  };
  if (meta("format", "") != "olympics-mlp")
    fail(path, "metadata \"format\" is \"" + meta("format", "") +
                   "\", expected \"olympics-mlp\" (docs/snapshots.md)");
  s.activation_ = meta("activation", "silu");
  s.output_ = meta("output", "none");
  if (s.activation_ != "silu" && s.activation_ != "relu" && s.activation_ != "tanh" &&
      s.activation_ != "elu")
    fail(path, "activation \"" + s.activation_ + "\" is not one of silu, relu, tanh, elu");
  if (s.output_ != "none" && s.output_ != "tanh")
    fail(path, "output \"" + s.output_ + "\" is not none or tanh");

  long in_size = -1;
  for (int layer = 0;; ++layer) {
    const std::string w = "layers." + std::to_string(layer) + ".weight";
    if (!header.contains(w)) break;
    auto shape = header[w].at("shape").get<std::vector<long>>();
    if (shape.size() != 2) fail(path, "tensor \"" + w + "\" is not a matrix");
    if (in_size >= 0 && shape[1] != in_size)
      fail(path, "tensor \"" + w + "\" takes " + std::to_string(shape[1]) +
                     " inputs, the layer before gives " + std::to_string(in_size));
    auto wdata = tensor(path, header, bytes, w, shape);
    auto bdata =
        tensor(path, header, bytes, "layers." + std::to_string(layer) + ".bias", {shape[0]});
    // safetensors is row-major [out, in]
    s.weights_.push_back(
        Eigen::Map<Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(
            wdata.data(), shape[0], shape[1]));
    s.biases_.push_back(Eigen::Map<Eigen::VectorXf>(bdata.data(), shape[0]));
    if (in_size < 0) s.obs_size_ = static_cast<int>(shape[1]);
    in_size = shape[0];
  }
  if (s.weights_.empty()) fail(path, "no tensor \"layers.0.weight\": not an MLP snapshot");
  s.action_size_ = static_cast<int>(in_size);
  for (const char* key : {"obs_size", "action_size"}) {
    const int declared = std::stoi(meta(key, "-1"));
    const int actual = std::string(key) == "obs_size" ? s.obs_size_ : s.action_size_;
    if (declared >= 0 && declared != actual)
      fail(path, std::string("metadata ") + key + " = " + std::to_string(declared) +
                     " but the layers say " + std::to_string(actual));
  }
  if (header.contains("obs_mean")) {
    auto mean = tensor(path, header, bytes, "obs_mean", {s.obs_size_});
    auto sd = tensor(path, header, bytes, "obs_std", {s.obs_size_});
    s.obs_mean_ = Eigen::Map<Eigen::VectorXf>(mean.data(), s.obs_size_);
    s.obs_std_ = Eigen::Map<Eigen::VectorXf>(sd.data(), s.obs_size_).cwiseMax(1e-8f);
  }
  return s;
}

std::string MlpSnapshot::describe() const {
  std::ostringstream out;
  out << path_ << ": MLP " << obs_size_;
  for (const auto& w : weights_) out << " -> " << w.rows();
  out << ", " << activation_ << " between layers, output " << output_
      << (obs_mean_.size() ? ", normalised observations" : "");
  for (const auto& [k, v] : metadata_) out << "\n  " << k << ": " << v;
  return out.str();
}

void MlpSnapshot::act(std::span<const float> observation, std::span<float> action) const {
  if (static_cast<int>(observation.size()) != obs_size_)
    throw std::invalid_argument(path_ + ": takes " + std::to_string(obs_size_) +
                                " observation floats, got " + std::to_string(observation.size()) +
                                " (is it for this sport and mode?)");
  Eigen::VectorXf x = Eigen::Map<const Eigen::VectorXf>(observation.data(), obs_size_);
  if (obs_mean_.size()) x = (x - obs_mean_).cwiseQuotient(obs_std_);
  for (size_t i = 0; i < weights_.size(); ++i) {
    x = weights_[i] * x + biases_[i];
    if (i + 1 == weights_.size()) break;
    if (activation_ == "silu")
      x = x.array() / (1.0f + (-x.array()).exp());
    else if (activation_ == "relu")
      x = x.cwiseMax(0.0f);
    else if (activation_ == "tanh")
      x = x.array().tanh();
    else
      x = (x.array() > 0).select(x.array(), x.array().exp() - 1.0f);  // elu
  }
  if (output_ == "tanh") x = x.array().tanh();
  for (int k = 0; k < action_size_ && k < static_cast<int>(action.size()); ++k) action[k] = x[k];
}

}  // namespace olympics::client
