#include "perception/recording/recording_mapping.hpp"

#include <cmath>
#include <filesystem>

#include "config/yaml_reader.hpp"

namespace handover::perception::recording {

namespace {

SignedAxis readAxis(const YamlReader& r) {
  const std::string s = r.asEnum({"x", "y", "z", "+x", "+y", "+z", "-x", "-y", "-z"});
  SignedAxis a;
  a.sign = s[0] == '-' ? -1.0 : 1.0;
  a.index = s.back() - 'x';
  return a;
}

std::vector<std::string> readNames(const YamlReader& r, std::size_t n) {
  if (!r.isSequence() || r.size() != n) r.fail("expected a list of " + std::to_string(n) + " column names");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(r.at(i).asString());
  return out;
}

/// Position and quaternion column names of a map, falling back to `def`.
void readColumns(const YamlReader& r, BodyColumns& c) {
  if (r.has("position")) c.position = readNames(r.child("position"), 3);
  if (r.has("quaternion")) c.quaternion = readNames(r.child("quaternion"), 4);
}

/// `file` and `columns` of a body, the top-level ones as defaults.
BodyColumns readBody(const YamlReader& r, const BodyColumns& def) {
  BodyColumns c = def;
  if (auto f = r.optionalChild("file")) c.file = f->asString();
  if (auto cols = r.optionalChild("columns")) {
    readColumns(*cols, c);
    cols->finish();
  }
  if (c.file.empty()) r.fail("no file (give `file` here or at the top of the mapping)");
  if (c.position.size() != 3 || c.quaternion.size() != 4) {
    r.fail("no columns (give `columns: {position: [...], quaternion: [...]}` here or at the top of the mapping)");
  }
  return c;
}

Eigen::Isometry3d readPosRpy(const YamlReader& r) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  if (auto p = r.optionalChild("pos")) T.translation() = p->asVector(3);
  if (auto a = r.optionalChild("rpy")) {
    const Eigen::Vector3d rpy = a->asVector(3);
    T.linear() = (Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
  }
  r.finish();
  return T;
}

double positive(const YamlReader& r) {
  const double v = r.asDouble();
  if (!(v > 0.0) || !std::isfinite(v)) r.fail("must be a positive number");
  return v;
}

RecordingMapping parse(const YamlReader& root, const std::string& base_dir) {
  if (!root.isMap()) root.fail("a recording mapping must be a map");
  RecordingMapping m;
  m.file = root.file();
  if (auto d = root.optionalChild("data")) {
    const std::filesystem::path p(d->asString());
    m.data_dir = (p.is_absolute() ? p : std::filesystem::path(base_dir) / p).lexically_normal().string();
  }
  if (auto t = root.optionalChild("time_column")) m.time_column = t->asString();
  if (auto r = root.optionalChild("rate_hz")) m.rate_hz = positive(*r);
  if (m.time_column.empty() && m.rate_hz <= 0.0) root.fail("give rate_hz (rows per second) or time_column");
  const std::string units = root.child("units").asEnum({"m", "cm", "mm"});
  m.units = units == "m" ? 1.0 : units == "cm" ? 0.01 : 0.001;
  m.up = readAxis(root.child("up"));
  m.scalar_first = root.child("quaternion").asEnum({"xyzw", "wxyz"}) == "wxyz";

  BodyColumns def;
  if (auto f = root.optionalChild("file")) def.file = f->asString();
  if (auto c = root.optionalChild("columns")) {
    readColumns(*c, def);
    c->finish();
  }

  {
    const YamlReader h = root.child("hand");
    m.hand.columns = readBody(h, def);
    m.hand.long_axis = readAxis(h.child("long_axis"));
    m.hand.back_axis = readAxis(h.child("back_axis"));
    if (m.hand.back_axis.index == m.hand.long_axis.index) h.child("back_axis").fail("must differ from long_axis");
    if (auto g = h.optionalChild("grip")) m.hand.grip = g->checkRange(g->asDouble(), 0.0, 0.3);
    h.finish();
  }
  for (auto [key, bone] : {std::pair{"forearm", &m.forearm}, std::pair{"upper_arm", &m.upper_arm}}) {
    const YamlReader b = root.child(key);
    bone->columns = readBody(b, def);
    bone->long_axis = readAxis(b.child("long_axis"));
    b.finish();
  }
  if (auto o = root.optionalChild("object")) {
    if (o->has("in_hand")) {
      m.object.in_hand = readPosRpy(o->child("in_hand"));
      if (o->has("file") || o->has("long_axis")) o->fail("give either in_hand or a tracked body (file, long_axis)");
    } else {
      m.object.tracked = true;
      m.object.columns = readBody(*o, def);
      if (auto a = o->optionalChild("long_axis")) m.object.long_axis = readAxis(*a);
    }
    if (auto s = o->optionalChild("shape")) m.object.shape = s->asEnum({"cylinder", "box", "sphere"});
    if (auto s = o->optionalChild("size")) {
      const std::size_t n = m.object.shape == "box" ? 3 : m.object.shape == "sphere" ? 1 : 2;
      const Eigen::VectorXd v = s->asVector(static_cast<int>(n));
      for (int i = 0; i < v.size(); ++i) {
        if (!(v[i] > 0.0)) s->fail("sizes must be positive");
        m.object.size.push_back(v[i]);
      }
    }
    o->finish();
  }
  {
    const YamlReader p = root.child("place");
    if (p.has("transform")) {
      m.place.rigid = true;
      m.place.transform = readPosRpy(p.child("transform"));
      if (p.has("receiver") || p.has("giver")) p.fail("give either transform or receiver and giver");
    } else {
      const YamlReader receiver = p.child("receiver"), giver = p.child("giver");
      m.place.receiver = readBody(receiver, def);
      receiver.finish();
      m.place.giver = readBody(giver, def);
      giver.finish();
      m.place.floor = p.getDouble("floor", 0.0);
    }
    if (auto s = p.optionalChild("shift")) m.place.shift = s->asVector(3);
    p.finish();
  }
  if (auto w = root.optionalChild("window")) {
    m.window_start = w->getDouble("start", 0.0);
    if (m.window_start < 0.0) w->child("start").fail("must be >= 0");
    if (auto e = w->optionalChild("end")) {
      m.window_end = e->asDouble();
      if (!(*m.window_end > m.window_start)) e->fail("must be after window.start");
    }
    w->finish();
  }
  if (auto s = root.optionalChild("speed")) m.speed = positive(*s);
  m.mirror = root.getBool("mirror", false);
  if (auto h = root.optionalChild("hold_end")) m.hold_end = h->checkRange(h->asDouble(), 0.0, 600.0);
  root.finish();
  return m;
}

}  // namespace

RecordingMapping loadRecordingMapping(const std::string& path) {
  const std::string base = std::filesystem::path(path).parent_path().string();
  return parse(YamlReader::loadFile(path), base.empty() ? "." : base);
}

RecordingMapping parseRecordingMapping(const std::string& text, const std::string& origin,
                                       const std::string& base_dir) {
  return parse(YamlReader::loadString(text, origin), base_dir);
}

}  // namespace handover::perception::recording
