// The scene template is sized from the load options: object shape/size/mass
// and the person's dimensions end up in the compiled MuJoCo model.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include "config/input_error.hpp"
#include "scenes/sim/scene_builder.hpp"
#include "scenes/sim/simulation.hpp"
#include "sim_test_support.hpp"

namespace handover::sim {
namespace {

TEST(SceneBuilder, ReplacesAddsAndSkipsComments) {
  std::string xml =
      "<!-- <geom name=\"g\" size=\"9\"/> -->\n<body><geom name=\"g\" size=\"1 2\"/><geom name=\"gg\"/></body>";
  ASSERT_TRUE(setElementAttribute(xml, "g", "size", "3 4"));
  ASSERT_TRUE(setElementAttribute(xml, "g", "mass", "0.5"));
  EXPECT_NE(xml.find("<geom name=\"g\" size=\"3 4\" mass=\"0.5\"/>"), std::string::npos) << xml;
  EXPECT_NE(xml.find("size=\"9\""), std::string::npos) << "the comment must stay untouched: " << xml;
  EXPECT_NE(xml.find("<geom name=\"gg\"/>"), std::string::npos) << xml;
  EXPECT_FALSE(setElementAttribute(xml, "absent", "size", "1"));
}

TEST(SceneBuilder, MissingNamedElementIsAnInputErrorNamingIt) {
  try {
    buildSceneXml("<mujoco><worldbody/></mujoco>", SimOptions{}, "my_scene.xml");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("my_scene.xml"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("object_geom"), std::string::npos) << e.what();
  }
}

TEST(SceneBuilder, BadOptionsAreInputErrorsNamingTheKey) {
  SimOptions o;
  o.object.shape = ObjectShape::Box;  // box needs three edges, default size has two
  try {
    validate(o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("object.size"), std::string::npos) << e.what();
  }
  o.object.size = {0.05, 0.05, 0.05};
  o.object.mass = -1.0;
  EXPECT_THROW(validate(o), InputError);
  o.object.mass = 0.2;
  o.human.forearm_length = 0.0;
  EXPECT_THROW(validate(o), InputError);
  EXPECT_THROW(parseObjectShape("cone"), InputError);
  EXPECT_EQ(parseObjectShape("sphere"), ObjectShape::Sphere);
}

TEST(SceneBuilder, ObjectAndPersonAreSizedFromTheOptions) {
  SimOptions o;
  o.object.shape = ObjectShape::Box;
  o.object.size = {0.06, 0.04, 0.10};
  o.object.mass = 0.42;
  o.human.forearm_length = 0.30;
  o.human.upper_arm_length = 0.36;
  Simulation sim;
  sim.load(o);
  const mjModel* m = sim.mujocoModel();
  const int g = mj_name2id(m, mjOBJ_GEOM, "object_geom");
  ASSERT_GE(g, 0);
  EXPECT_EQ(m->geom_type[g], mjGEOM_BOX);
  EXPECT_NEAR(m->geom_size[3 * g + 0], 0.03, 1e-12);
  EXPECT_NEAR(m->geom_size[3 * g + 1], 0.02, 1e-12);
  EXPECT_NEAR(m->geom_size[3 * g + 2], 0.05, 1e-12);
  EXPECT_NEAR(m->body_mass[mj_name2id(m, mjOBJ_BODY, "object")], 0.42, 1e-12);
  const int fa = mj_name2id(m, mjOBJ_GEOM, "human_forearm_geom");
  EXPECT_NEAR(2 * m->geom_size[3 * fa + 1], 0.30, 1e-12);
  const int ua = mj_name2id(m, mjOBJ_GEOM, "human_upper_arm_geom");
  EXPECT_NEAR(2 * m->geom_size[3 * ua + 1], 0.36, 1e-12);

  // the box rests on the table top (z = 0) on its 10 cm edge
  for (int i = 0; i < 300; ++i) test::holdStep(sim, test::readyPosture());
  EXPECT_NEAR(sim.object().pose.translation().z(), 0.05, 1e-3);
  EXPECT_TRUE(sim.contacts().object_on_table);
}

TEST(SceneBuilder, SphereObject) {
  SimOptions o;
  o.object.shape = ObjectShape::Sphere;
  o.object.size = {0.04};
  Simulation sim;
  sim.load(o);
  const mjModel* m = sim.mujocoModel();
  const int g = mj_name2id(m, mjOBJ_GEOM, "object_geom");
  EXPECT_EQ(m->geom_type[g], mjGEOM_SPHERE);
  EXPECT_NEAR(m->geom_size[3 * g], 0.04, 1e-12);
}

}  // namespace
}  // namespace handover::sim
