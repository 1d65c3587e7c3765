#include "core/action_map.h"

#include <cmath>
#include <limits>

#include "core/mjcf_loader.h"
#include "test_support.h"

namespace olympics::core {
namespace {

TEST(ActionMap, PiPerHingeAndFiveForKneeFlexion) {
  const ModelSpec& s = testing::smpl();
  ActionMap map(s);
  ASSERT_EQ(map.size(), 69);
  auto names = s.hinge_names();
  for (int i = 0; i < map.size(); ++i) {
    bool knee_flexion = names[i] == "L_Knee_y" || names[i] == "R_Knee_y";
    EXPECT_DOUBLE_EQ(map.scales()[i], knee_flexion ? 5.0 : M_PI) << names[i];
  }
}

TEST(ActionMap, ScaleFollowsTheRangeLikeTheOriginal) {
  ModelSpec m = load_mjcf_string(
      "<mujoco><worldbody><body name=\"P\"><freejoint/><geom size=\"0.1\"/>"
      "<body name=\"A\"><joint name=\"x\" axis=\"1 0 0\" range=\"-90 90\"/>"
      "<joint name=\"y\" axis=\"0 1 0\" range=\"-10 5\"/><joint name=\"z\" axis=\"0 0 1\"/>"
      "<geom size=\"0.1\"/></body></body></worldbody></mujoco>",
      "inline.xml");
  ActionMap map(m);
  EXPECT_NEAR(map.scales()[0], 1.2 * M_PI / 2, 1e-12);
  EXPECT_NEAR(map.scales()[1], 1.2 * 10 * M_PI / 180, 1e-12);
  EXPECT_NEAR(map.scales()[2], M_PI, 1e-12);  // no range given
}

TEST(ActionMap, RefusesWrongSizeAndNonFinite) {
  ActionMap map(testing::smpl());
  std::vector<float> a(69, 0.5f);
  std::vector<double> out(69);
  map.targets(a, out);
  EXPECT_NEAR(out[0], 0.5 * M_PI, 1e-6);
  std::vector<float> short_action(68, 0.0f);
  EXPECT_THROW(map.targets(short_action, out), std::invalid_argument);
  a[7] = std::numeric_limits<float>::quiet_NaN();
  try {
    map.targets(a, out);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("action[7] is not finite"), std::string::npos);
  }
  a[7] = std::numeric_limits<float>::infinity();
  EXPECT_THROW(map.targets(a, out), std::invalid_argument);
}

}  // namespace
}  // namespace olympics::core
