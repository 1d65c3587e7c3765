// The same humanoid scene in MuJoCo, for side-by-side physics cost (olympics-bench physics).
//
// MuJoCo reads the project's own MJCF file itself. To make it the same control problem, the file
// is copied N times into one model (names prefixed, pelvis placed like ours), the joints' passive
// stiffness is removed, and each hinge gets a position actuator with the joint's kp; the joint's
// damping stays as MuJoCo's (implicitly integrated) joint damping kd. Timestep is ours.
#pragma once

#include <mujoco/mujoco.h>

#include <span>
#include <string>
#include <vector>

namespace olympics::bench {

struct MujocoSceneOptions {
  std::string asset_path;
  int humanoids = 1;
  double timestep = 1.0 / 120;
  double spacing = 1.0;       // metres between humanoids along x
  double root_height = 0.94;  // pelvis origin
  bool match_solver = false;  // PGS with our iteration count instead of MuJoCo's defaults
  int solver_iterations = 8;
  std::string integrator;  // empty: MuJoCo's default (Euler)
};

class MujocoScene {
 public:
  explicit MujocoScene(const MujocoSceneOptions& options);
  ~MujocoScene();
  MujocoScene(const MujocoScene&) = delete;
  MujocoScene& operator=(const MujocoScene&) = delete;

  int actuator_count() const { return model_->nu; }
  // Position targets (radians) for humanoid h, one per hinge in file order.
  void set_targets(int humanoid, std::span<const double> targets);
  void step() { mj_step(model_, data_); }
  // False once MuJoCo has diverged (it then resets the state and warns).
  bool finite() const;
  long model_bytes() const { return static_cast<long>(model_->nbuffer + data_->nbuffer); }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  int per_humanoid_ = 0;
};

}  // namespace olympics::bench
