#include "core/mjcf_loader.h"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <sstream>
#include <vector>

namespace olympics::core {
namespace {

using tinyxml2::XMLElement;

// Attribute defaults of one <default> class, per element tag, with the class it inherits from.
struct DefaultClass {
  std::string parent;
  std::map<std::string, std::map<std::string, std::string>> attrs;  // tag -> attr -> value
};

class Reader {
 public:
  Reader(std::string source, const MjcfLoadOptions& options)
      : source_(std::move(source)), options_(options) {}

  ModelSpec read(const XMLElement* root);

 private:
  [[noreturn]] void fail(const XMLElement* e, const std::string& problem) const {
    std::ostringstream msg;
    msg << source_ << ":" << (e ? e->GetLineNum() : 0) << ": ";
    if (e) {
      msg << "<" << e->Name();
      if (const char* n = e->Attribute("name")) msg << " name=\"" << n << "\"";
      msg << ">: ";
    }
    msg << problem;
    throw MjcfError(msg.str());
  }

  void read_defaults(const XMLElement* e, const std::string& class_name, const std::string& parent);
  std::optional<std::string> attr(const XMLElement* e, const std::string& name,
                                  const std::string& cls) const;
  std::vector<double> numbers(const XMLElement* e, const std::string& name, const std::string& cls,
                              size_t min_count, size_t max_count) const;
  std::optional<double> number(const XMLElement* e, const std::string& name,
                               const std::string& cls) const;
  Eigen::Quaterniond orientation(const XMLElement* e, const std::string& cls) const;
  double angle(double value) const { return degrees_ ? value * M_PI / 180.0 : value; }

  void read_body(const XMLElement* e, int parent, const std::string& inherited_class);
  HingeSpec read_hinge(const XMLElement* e, const std::string& cls) const;
  GeomSpec read_geom(const XMLElement* e, const std::string& cls) const;
  void convert_y_up_to_z_up();
  bool looks_y_up() const;

  std::string source_;
  MjcfLoadOptions options_;
  bool degrees_ = true;
  std::map<std::string, DefaultClass> classes_;
  ModelSpec model_;
};

void Reader::read_defaults(const XMLElement* e, const std::string& class_name,
                           const std::string& parent) {
  DefaultClass& cls = classes_[class_name];
  cls.parent = parent;
  for (auto* child = e->FirstChildElement(); child; child = child->NextSiblingElement()) {
    std::string tag = child->Name();
    if (tag == "default") {
      const char* name = child->Attribute("class");
      if (!name) fail(child, "a nested <default> needs a class attribute");
      read_defaults(child, name, class_name);
      continue;
    }
    for (auto* a = child->FirstAttribute(); a; a = a->Next())
      cls.attrs[tag][a->Name()] = a->Value();
  }
}

std::optional<std::string> Reader::attr(const XMLElement* e, const std::string& name,
                                        const std::string& cls) const {
  if (const char* v = e->Attribute(name.c_str())) return std::string(v);
  std::string tag = e->Name();
  if (tag == "freejoint") tag = "joint";
  for (std::string c = cls; !c.empty();) {
    auto it = classes_.find(c);
    if (it == classes_.end()) break;
    auto t = it->second.attrs.find(tag);
    if (t != it->second.attrs.end()) {
      auto a = t->second.find(name);
      if (a != t->second.end()) return a->second;
    }
    c = it->second.parent;
  }
  return std::nullopt;
}

std::vector<double> Reader::numbers(const XMLElement* e, const std::string& name,
                                    const std::string& cls, size_t min_count,
                                    size_t max_count) const {
  auto text = attr(e, name, cls);
  if (!text) return {};
  std::vector<double> out;
  std::istringstream in(*text);
  std::string token;
  while (in >> token) {
    char* end = nullptr;
    double v = std::strtod(token.c_str(), &end);
    if (end == token.c_str() || *end != '\0' || !std::isfinite(v))
      fail(e, "attribute " + name + "=\"" + *text + "\" is not a list of finite numbers");
    out.push_back(v);
  }
  if (out.size() < min_count || out.size() > max_count) {
    std::ostringstream msg;
    msg << "attribute " << name << "=\"" << *text << "\" has " << out.size()
        << " numbers, expected " << min_count;
    if (max_count != min_count) msg << " to " << max_count;
    fail(e, msg.str());
  }
  return out;
}

std::optional<double> Reader::number(const XMLElement* e, const std::string& name,
                                     const std::string& cls) const {
  auto v = numbers(e, name, cls, 1, 1);
  if (v.empty()) return std::nullopt;
  return v[0];
}

Eigen::Quaterniond Reader::orientation(const XMLElement* e, const std::string& cls) const {
  if (auto q = numbers(e, "quat", cls, 4, 4); !q.empty()) {
    Eigen::Quaterniond quat(q[0], q[1], q[2], q[3]);
    if (quat.norm() < 1e-12) fail(e, "quat has zero length");
    return quat.normalized();
  }
  if (auto aa = numbers(e, "axisangle", cls, 4, 4); !aa.empty()) {
    Eigen::Vector3d axis(aa[0], aa[1], aa[2]);
    if (axis.norm() < 1e-12) fail(e, "axisangle has a zero axis");
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle(aa[3]), axis.normalized()));
  }
  if (auto eu = numbers(e, "euler", cls, 3, 3); !eu.empty()) {
    // MuJoCo's default eulerseq "xyz": intrinsic rotations about x, then y, then z.
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle(eu[0]), Eigen::Vector3d::UnitX()) *
                              Eigen::AngleAxisd(angle(eu[1]), Eigen::Vector3d::UnitY()) *
                              Eigen::AngleAxisd(angle(eu[2]), Eigen::Vector3d::UnitZ()));
  }
  return Eigen::Quaterniond::Identity();
}

HingeSpec Reader::read_hinge(const XMLElement* e, const std::string& cls) const {
  HingeSpec h;
  const char* name = e->Attribute("name");
  if (!name) fail(e, "every joint needs a name (it names an action entry)");
  h.name = name;
  auto pos = numbers(e, "pos", cls, 3, 3);
  if (!pos.empty() && Eigen::Vector3d(pos[0], pos[1], pos[2]).norm() > 1e-9)
    fail(e, "hinges must sit at the body origin (pos=\"0 0 0\")");
  auto axis = numbers(e, "axis", cls, 3, 3);
  if (!axis.empty()) h.axis = Eigen::Vector3d(axis[0], axis[1], axis[2]);
  if (h.axis.norm() < 1e-12) fail(e, "axis has zero length");
  h.axis.normalize();
  if (auto range = numbers(e, "range", cls, 2, 2); !range.empty()) {
    if (range[0] > range[1]) fail(e, "range lower bound is above the upper bound");
    h.range_lo = angle(range[0]);
    h.range_hi = angle(range[1]);
  }
  // Gains: the `user` field (kp kd gear max_torque ...) wins, as in SMPL-X files; else the
  // stiffness/damping pair, as in SMPLSim's SMPL files.
  if (auto user = numbers(e, "user", cls, 0, 64); user.size() >= 2) {
    h.kp = user[0];
    h.kd = user[1];
  } else {
    h.kp = number(e, "stiffness", cls).value_or(0.0);
    h.kd = number(e, "damping", cls).value_or(0.0);
  }
  if (h.kp < 0 || h.kd < 0) fail(e, "PD gains must not be negative");
  h.armature = number(e, "armature", cls).value_or(0.0);
  return h;
}

GeomSpec Reader::read_geom(const XMLElement* e, const std::string& cls) const {
  GeomSpec g;
  if (const char* name = e->Attribute("name")) g.name = name;
  std::string type = attr(e, "type", cls).value_or("sphere");
  if (type == "sphere")
    g.shape = GeomShape::Sphere;
  else if (type == "capsule")
    g.shape = GeomShape::Capsule;
  else if (type == "cylinder")
    g.shape = GeomShape::Cylinder;
  else if (type == "box")
    g.shape = GeomShape::Box;
  else
    fail(e, "geom type \"" + type + "\" is not supported (sphere, capsule, cylinder, box)");

  auto size = numbers(e, "size", cls, 1, 3);
  auto fromto = numbers(e, "fromto", cls, 6, 6);
  if (size.empty()) fail(e, "geom needs a size");
  if (!fromto.empty()) {
    if (g.shape == GeomShape::Sphere || g.shape == GeomShape::Box)
      fail(e, "fromto is only for capsules and cylinders");
    Eigen::Vector3d a(fromto[0], fromto[1], fromto[2]), b(fromto[3], fromto[4], fromto[5]);
    Eigen::Vector3d d = b - a;
    if (d.norm() < 1e-12) fail(e, "fromto end points coincide");
    g.pos = 0.5 * (a + b);
    g.quat = Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), d.normalized());
    g.half_length = 0.5 * d.norm();
    g.radius = size[0];
  } else {
    auto pos = numbers(e, "pos", cls, 3, 3);
    if (!pos.empty()) g.pos = Eigen::Vector3d(pos[0], pos[1], pos[2]);
    g.quat = orientation(e, cls);
    if (g.shape == GeomShape::Box) {
      if (size.size() != 3) fail(e, "a box needs three half-extents in size");
      g.half_extents = Eigen::Vector3d(size[0], size[1], size[2]);
    } else {
      g.radius = size[0];
      if (g.shape != GeomShape::Sphere) {
        if (size.size() < 2)
          fail(e, "a capsule or cylinder without fromto needs size=\"r half_length\"");
        g.half_length = size[1];
      }
    }
  }
  if (g.radius < 0 || g.half_length < 0 || g.half_extents.minCoeff() < 0)
    fail(e, "geom sizes must not be negative");
  if (g.shape != GeomShape::Box && g.radius <= 0) fail(e, "geom radius must be positive");
  if (g.shape == GeomShape::Box && g.half_extents.minCoeff() <= 0)
    fail(e, "box half-extents must be positive");
  g.density = number(e, "density", cls).value_or(1000.0);
  if (auto m = number(e, "mass", cls)) g.mass = *m;
  if (g.density < 0 || (g.mass && *g.mass < 0)) fail(e, "mass and density must not be negative");
  if (auto f = numbers(e, "friction", cls, 1, 3); !f.empty()) g.friction = f[0];
  return g;
}

void Reader::read_body(const XMLElement* e, int parent, const std::string& inherited_class) {
  std::string cls = inherited_class;
  if (const char* c = e->Attribute("childclass")) cls = c;
  BodySpec body;
  const char* name = e->Attribute("name");
  if (!name) fail(e, "every body needs a name");
  body.name = name;
  if (model_.body_index(body.name) >= 0) fail(e, "body name is used twice");
  body.parent = parent;
  if (auto pos = numbers(e, "pos", cls, 3, 3); !pos.empty())
    body.pos = Eigen::Vector3d(pos[0], pos[1], pos[2]);
  body.quat = orientation(e, cls);

  for (auto* c = e->FirstChildElement(); c; c = c->NextSiblingElement()) {
    std::string tag = c->Name();
    std::string ccls = c->Attribute("class") ? c->Attribute("class") : cls;
    if (tag == "freejoint") {
      body.free_root = true;
    } else if (tag == "joint") {
      std::string type = attr(c, "type", ccls).value_or("hinge");
      if (type == "free")
        body.free_root = true;
      else if (type == "hinge")
        body.hinges.push_back(read_hinge(c, ccls));
      else
        fail(c, "joint type \"" + type + "\" is not supported; write three hinges (x, y, z)");
    } else if (tag == "geom") {
      body.geoms.push_back(read_geom(c, ccls));
      if (body.geoms.back().name.empty()) body.geoms.back().name = body.name;
    }
  }
  if (parent < 0 && !body.free_root) fail(e, "the root body needs a free joint");
  if (parent >= 0 && body.free_root) fail(e, "only the root body may have a free joint");
  if (!body.hinges.empty() && body.hinges.size() != 3)
    fail(e, "a body needs 0 or 3 hinges (the SMPL convention), found " +
                std::to_string(body.hinges.size()));
  if (body.hinges.size() == 3) {
    Eigen::Matrix3d axes;
    for (int i = 0; i < 3; ++i) axes.col(i) = body.hinges[i].axis;
    if (std::abs(axes.determinant()) < 1e-6) fail(e, "the three hinge axes are not independent");
  }
  int index = static_cast<int>(model_.bodies.size());
  model_.bodies.push_back(std::move(body));
  for (auto* c = e->FirstChildElement("body"); c; c = c->NextSiblingElement("body"))
    read_body(c, index, cls);
}

bool Reader::looks_y_up() const {
  for (size_t i = 0; i < model_.bodies.size(); ++i) {
    std::string lower = model_.bodies[i].name;
    std::transform(lower.begin(), lower.end(), lower.begin(), ::tolower);
    if (lower != "head") continue;
    Eigen::Vector3d p = Eigen::Vector3d::Zero();
    for (int b = static_cast<int>(i); model_.bodies[b].parent >= 0; b = model_.bodies[b].parent)
      p = model_.bodies[b].quat * p + model_.bodies[b].pos;
    Eigen::Index axis;
    p.cwiseAbs().maxCoeff(&axis);
    return axis == 1 && p.y() > 0;
  }
  return false;
}

void Reader::convert_y_up_to_z_up() {
  // here = (z, x, y) of the source: a cyclic permutation, hence a proper rotation.
  auto v = [](const Eigen::Vector3d& s) { return Eigen::Vector3d(s.z(), s.x(), s.y()); };
  auto q = [&](const Eigen::Quaterniond& s) {
    Eigen::Vector3d xyz = v(s.vec());
    return Eigen::Quaterniond(s.w(), xyz.x(), xyz.y(), xyz.z());
  };
  for (size_t i = 0; i < model_.bodies.size(); ++i) {
    BodySpec& b = model_.bodies[i];
    // The root's position is a template offset in the source frame; children are relative.
    b.pos = v(b.pos);
    b.quat = q(b.quat);
    for (auto& h : b.hinges) h.axis = v(h.axis);
    for (auto& g : b.geoms) {
      g.pos = v(g.pos);
      g.quat = q(g.quat);
      g.half_extents = v(g.half_extents);
    }
  }
}

ModelSpec Reader::read(const XMLElement* root) {
  if (!root || std::string(root->Name()) != "mujoco")
    fail(root, "the top element must be <mujoco>");
  model_.source = source_;
  if (auto* compiler = root->FirstChildElement("compiler")) {
    if (const char* a = compiler->Attribute("angle")) {
      std::string v = a;
      if (v != "degree" && v != "radian") fail(compiler, "angle must be degree or radian");
      degrees_ = v == "degree";
    }
    if (const char* c = compiler->Attribute("coordinate"); c && std::string(c) != "local")
      fail(compiler, "only coordinate=\"local\" is supported");
  }
  if (auto* option = root->FirstChildElement("option"))
    if (auto dt = number(option, "timestep", "")) {
      if (*dt <= 0) fail(option, "timestep must be positive");
      model_.timestep = *dt;
    }
  for (auto* d = root->FirstChildElement("default"); d; d = d->NextSiblingElement("default"))
    read_defaults(d, d->Attribute("class") ? d->Attribute("class") : "main", "");

  auto* world = root->FirstChildElement("worldbody");
  if (!world) fail(root, "no <worldbody>");
  int roots = 0;
  for (auto* b = world->FirstChildElement("body"); b; b = b->NextSiblingElement("body")) {
    if (++roots > 1) fail(b, "a humanoid file has exactly one root body; found a second");
    read_body(b, -1, "main");
  }
  if (roots == 0) fail(world, "no body in <worldbody>");

  for (auto* c = root->FirstChildElement("contact"); c; c = c->NextSiblingElement("contact"))
    for (auto* x = c->FirstChildElement("exclude"); x; x = x->NextSiblingElement("exclude")) {
      const char* b1 = x->Attribute("body1");
      const char* b2 = x->Attribute("body2");
      if (!b1 || !b2) fail(x, "exclude needs body1 and body2");
      int i1 = model_.body_index(b1), i2 = model_.body_index(b2);
      if (i1 < 0 || i2 < 0) fail(x, std::string("unknown body \"") + (i1 < 0 ? b1 : b2) + "\"");
      model_.contact_excludes.emplace_back(i1, i2);
    }

  bool y_up = options_.up == UpAxis::Y || (options_.up == UpAxis::Auto && looks_y_up());
  if (y_up) convert_y_up_to_z_up();
  return std::move(model_);
}

ModelSpec parse(tinyxml2::XMLDocument& doc, const std::string& source, const MjcfLoadOptions& o) {
  if (doc.Error()) {
    std::ostringstream msg;
    msg << source << ":" << doc.ErrorLineNum() << ": malformed XML: " << doc.ErrorStr();
    throw MjcfError(msg.str());
  }
  return Reader(source, o).read(doc.RootElement());
}

}  // namespace

ModelSpec load_mjcf_file(const std::string& path, const MjcfLoadOptions& options) {
  tinyxml2::XMLDocument doc;
  if (doc.LoadFile(path.c_str()) == tinyxml2::XML_ERROR_FILE_NOT_FOUND ||
      doc.ErrorID() == tinyxml2::XML_ERROR_FILE_COULD_NOT_BE_OPENED)
    throw MjcfError(path + ": cannot open the file (check the path)");
  return parse(doc, path, options);
}

ModelSpec load_mjcf_string(const std::string& xml, const std::string& name_for_errors,
                           const MjcfLoadOptions& options) {
  tinyxml2::XMLDocument doc;
  doc.Parse(xml.c_str(), xml.size());
  return parse(doc, name_for_errors, options);
}

}  // namespace olympics::core
