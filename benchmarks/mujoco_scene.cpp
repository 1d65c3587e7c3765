#include "mujoco_scene.h"

#include <tinyxml2.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace olympics::bench {
namespace {

using tinyxml2::XMLElement;

void prefix_names(XMLElement* e, const std::string& prefix) {
  for (const char* attr : {"name", "joint", "body1", "body2"})
    if (const char* v = e->Attribute(attr)) e->SetAttribute(attr, (prefix + v).c_str());
  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) prefix_names(c, prefix);
}

void collect_hinges(XMLElement* body, std::vector<XMLElement*>& out) {
  for (auto* j = body->FirstChildElement("joint"); j; j = j->NextSiblingElement("joint"))
    out.push_back(j);
  for (auto* b = body->FirstChildElement("body"); b; b = b->NextSiblingElement("body"))
    collect_hinges(b, out);
}

}  // namespace

MujocoScene::MujocoScene(const MujocoSceneOptions& o) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(o.asset_path.c_str()) != tinyxml2::XML_SUCCESS)
    throw std::runtime_error("cannot read " + o.asset_path);
  XMLElement* root = doc.RootElement();
  XMLElement* world = root->FirstChildElement("worldbody");
  XMLElement* pelvis = world->FirstChildElement("body");
  XMLElement* contact = root->FirstChildElement("contact");

  if (auto* option = root->FirstChildElement("option")) root->DeleteChild(option);
  XMLElement* option = doc.NewElement("option");
  option->SetAttribute("timestep", o.timestep);
  if (o.match_solver) {
    option->SetAttribute("solver", "PGS");
    option->SetAttribute("iterations", o.solver_iterations);
  }
  if (!o.integrator.empty()) option->SetAttribute("integrator", o.integrator.c_str());
  root->InsertFirstChild(option);
  if (auto* size = root->FirstChildElement("size")) root->DeleteChild(size);
  XMLElement* size = doc.NewElement("size");  // room for every contact of N humanoids
  size->SetAttribute("nconmax", 200 * o.humanoids);
  size->SetAttribute("njmax", 1000 * o.humanoids);
  root->InsertAfterChild(option, size);

  XMLElement* actuators = doc.NewElement("actuator");
  XMLElement* excludes = doc.NewElement("contact");
  for (int h = 0; h < o.humanoids; ++h) {
    char prefix_buf[16];
    std::snprintf(prefix_buf, sizeof prefix_buf, "h%d_", h);
    const std::string prefix = prefix_buf;
    auto* copy = pelvis->DeepClone(&doc)->ToElement();
    prefix_names(copy, prefix);
    char pos[64];
    std::snprintf(pos, sizeof pos, "%g 0 %g", h * o.spacing, o.root_height);
    copy->SetAttribute("pos", pos);
    if (h % 2 == 1) copy->SetAttribute("euler", "0 0 180");
    std::vector<XMLElement*> hinges;
    collect_hinges(copy, hinges);
    for (auto* j : hinges) {
      double kp = j->DoubleAttribute("stiffness", 0);
      j->SetAttribute("stiffness", 0);  // a passive spring to the rest pose is not our PD
      auto* act = doc.NewElement("position");
      act->SetAttribute("joint", j->Attribute("name"));
      act->SetAttribute("kp", kp);
      actuators->InsertEndChild(act);
    }
    per_humanoid_ = static_cast<int>(hinges.size());
    world->InsertEndChild(copy);
    if (contact)
      for (auto* x = contact->FirstChildElement("exclude"); x;
           x = x->NextSiblingElement("exclude")) {
        auto* e = x->DeepClone(&doc)->ToElement();
        prefix_names(e, prefix);
        excludes->InsertEndChild(e);
      }
  }
  world->DeleteChild(pelvis);
  if (contact) root->DeleteChild(contact);
  root->InsertEndChild(excludes);
  root->InsertEndChild(actuators);

  char path[] = "/tmp/olympics-mujoco-XXXXXX.xml";
  int fd = mkstemps(path, 4);
  if (fd < 0) throw std::runtime_error("cannot create a temporary file for MuJoCo");
  close(fd);
  doc.SaveFile(path);
  char error[1000] = "";
  model_ = mj_loadXML(path, nullptr, error, sizeof error);
  std::remove(path);
  if (!model_) throw std::runtime_error(std::string("MuJoCo refused the scene: ") + error);
  data_ = mj_makeData(model_);
  mj_forward(model_, data_);
}

MujocoScene::~MujocoScene() {
  mj_deleteData(data_);
  mj_deleteModel(model_);
}

void MujocoScene::set_targets(int humanoid, std::span<const double> targets) {
  for (int i = 0; i < per_humanoid_; ++i) data_->ctrl[humanoid * per_humanoid_ + i] = targets[i];
}

bool MujocoScene::finite() const {
  // MuJoCo resets the state itself when it diverges and counts it as a bad-QACC warning.
  return data_->warning[mjWARN_BADQACC].number == 0;
}

}  // namespace olympics::bench
