// Frozen policy snapshots: an MLP in a safetensors file (docs/snapshots.md), run with Eigen.
//
// Tensors "layers.<i>.weight" [out, in] and "layers.<i>.bias" [out], float32, i = 0..L-1, and
// optionally "obs_mean" / "obs_std" [obs_size]; metadata "format" = "olympics-mlp", "activation"
// (silu, relu, tanh, elu) between layers, "output" (none or tanh) after the last, "obs_size",
// "action_size", and free-form "policy_id", "policy_version", "sport".
#pragma once

#include <Eigen/Dense>
#include <map>
#include <span>
#include <string>
#include <vector>

namespace olympics::client {

class MlpSnapshot {
 public:
  // Throws std::runtime_error naming the file, the tensor or key, and the problem.
  static MlpSnapshot load(const std::string& path);

  int obs_size() const { return obs_size_; }
  int action_size() const { return action_size_; }
  const std::map<std::string, std::string>& metadata() const { return metadata_; }
  std::string describe() const;
  void act(std::span<const float> observation, std::span<float> action) const;

 private:
  std::string path_;
  std::map<std::string, std::string> metadata_;
  std::vector<Eigen::MatrixXf> weights_;
  std::vector<Eigen::VectorXf> biases_;
  Eigen::VectorXf obs_mean_, obs_std_;
  std::string activation_, output_;
  int obs_size_ = 0, action_size_ = 0;
};

}  // namespace olympics::client
