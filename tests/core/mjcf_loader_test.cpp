// Bad MJCF gets an error that names the file, the line, the element and the problem.
#include "core/mjcf_loader.h"

#include <gtest/gtest.h>

namespace olympics::core {
namespace {

std::string error_of(const std::string& xml) {
  try {
    load_mjcf_string(xml, "bad.xml");
  } catch (const MjcfError& e) {
    return e.what();
  }
  return "";
}

std::string humanoid_with_body(const std::string& child) {
  return "<mujoco>\n<worldbody>\n<body name=\"Pelvis\">\n<freejoint/>\n"
         "<geom type=\"sphere\" size=\"0.1\"/>\n" +
         child + "\n</body>\n</worldbody>\n</mujoco>";
}

TEST(MjcfLoader, MissingFileSaysSo) {
  try {
    load_mjcf_file("/nonexistent/humanoid.xml");
    FAIL() << "no error";
  } catch (const MjcfError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/humanoid.xml: cannot open"),
              std::string::npos);
  }
}

TEST(MjcfLoader, MalformedXmlNamesTheLine) {
  std::string e = error_of("<mujoco>\n<worldbody>\n<body name=\"a\">\n</worldbody>\n</mujoco>");
  EXPECT_NE(e.find("bad.xml:"), std::string::npos) << e;
  EXPECT_NE(e.find("malformed XML"), std::string::npos) << e;
}

TEST(MjcfLoader, WrongTopElement) {
  EXPECT_NE(error_of("<robot/>").find("top element must be <mujoco>"), std::string::npos);
}

TEST(MjcfLoader, UnsupportedGeomTypeNamesElementAndLine) {
  std::string e = error_of(
      humanoid_with_body("<body name=\"Arm\"><geom name=\"g\" type=\"mesh\" size=\"1\"/></body>"));
  EXPECT_NE(e.find("bad.xml:6: <geom name=\"g\">"), std::string::npos) << e;
  EXPECT_NE(e.find("\"mesh\" is not supported"), std::string::npos) << e;
}

TEST(MjcfLoader, BadNumbersAreRejected) {
  std::string e = error_of(
      humanoid_with_body("<body name=\"Arm\" pos=\"0 zero 0\"><geom size=\"0.1\"/></body>"));
  EXPECT_NE(e.find("<body name=\"Arm\">"), std::string::npos) << e;
  EXPECT_NE(e.find("pos=\"0 zero 0\" is not a list of finite numbers"), std::string::npos) << e;
  e = error_of(humanoid_with_body("<body name=\"Arm\" pos=\"0 0\"><geom size=\"0.1\"/></body>"));
  EXPECT_NE(e.find("has 2 numbers, expected 3"), std::string::npos) << e;
  e = error_of(humanoid_with_body("<body name=\"Arm\"><geom size=\"nan\"/></body>"));
  EXPECT_NE(e.find("not a list of finite numbers"), std::string::npos) << e;
}

TEST(MjcfLoader, TwoHingesAreRefusedWithTheReason) {
  std::string e = error_of(humanoid_with_body(
      "<body name=\"Arm\"><joint name=\"a\" axis=\"1 0 0\"/><joint name=\"b\" axis=\"0 1 0\"/>"
      "<geom size=\"0.1\"/></body>"));
  EXPECT_NE(e.find("<body name=\"Arm\">: a body needs 0 or 3 hinges"), std::string::npos) << e;
}

TEST(MjcfLoader, RootWithoutFreeJointAndUnknownExclude) {
  EXPECT_NE(
      error_of("<mujoco><worldbody><body name=\"P\"><geom size=\"1\"/></body></worldbody></mujoco>")
          .find("root body needs a free joint"),
      std::string::npos);
  std::string e = error_of(
      "<mujoco><worldbody><body name=\"P\"><freejoint/><geom size=\"1\"/></body></worldbody>"
      "<contact><exclude body1=\"P\" body2=\"Q\"/></contact></mujoco>");
  EXPECT_NE(e.find("unknown body \"Q\""), std::string::npos) << e;
}

TEST(MjcfLoader, DefaultsClassesAndFromtoAreApplied) {
  ModelSpec m = load_mjcf_string(
      "<mujoco><compiler angle=\"radian\"/><option timestep=\"0.005\"/>"
      "<default><joint stiffness=\"7\" damping=\"3\" range=\"-1 1\"/>"
      "<default class=\"soft\"><joint stiffness=\"2\"/></default></default>"
      "<worldbody><body name=\"P\"><freejoint/><geom type=\"box\" size=\"0.1 0.2 0.3\"/>"
      "<body name=\"C\" pos=\"0 0 1\"><joint name=\"x\" axis=\"1 0 0\"/>"
      "<joint name=\"y\" class=\"soft\" axis=\"0 1 0\"/><joint name=\"z\" axis=\"0 0 2\"/>"
      "<geom type=\"capsule\" size=\"0.05\" fromto=\"0 0 0 0 0 "
      "-0.4\"/></body></body></worldbody></mujoco>",
      "inline.xml");
  ASSERT_EQ(m.bodies.size(), 2u);
  EXPECT_DOUBLE_EQ(m.timestep, 0.005);
  const BodySpec& c = m.bodies[1];
  EXPECT_EQ(c.hinges[0].kp, 7);
  EXPECT_EQ(c.hinges[1].kp, 2);                 // class overrides the main default
  EXPECT_EQ(c.hinges[1].kd, 3);                 // and inherits what it does not set
  EXPECT_DOUBLE_EQ(c.hinges[0].range_hi, 1.0);  // radians, as the compiler says
  EXPECT_NEAR(c.hinges[2].axis.norm(), 1.0, 1e-12);
  const GeomSpec& g = c.geoms[0];
  EXPECT_NEAR(g.half_length, 0.2, 1e-12);
  EXPECT_NEAR(g.pos.z(), -0.2, 1e-12);
  EXPECT_EQ(m.dof_count(), 3);
}

}  // namespace
}  // namespace olympics::core
