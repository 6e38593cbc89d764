// Domain files (.json): parsed with nlohmann::json; every value is read through a JsonValue
// that knows its path in the file, so that an error names the file and the path.
#include "volmesh/io/domain_file.hpp"

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>

#include "volmesh/core/errors.hpp"
#include "volmesh/domain/analytic_csg.hpp"
#include "volmesh/domain/layered.hpp"
#include "volmesh/domain/prioritized.hpp"
#include "volmesh/domain/surface.hpp"
#include "volmesh/io/surface_io.hpp"

namespace volmesh {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct FileContext {
  std::string name;  // the file as given, for messages
  fs::path dir;      // relative paths are taken from here
};

class JsonValue {
 public:
  JsonValue(const json& value, std::string path, const FileContext& file)
      : value_(value), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail(const std::string& what) const {
    throw InputError(file_.name + ": " + (path_.empty() ? "" : path_ + ": ") + what);
  }
  const std::string& path() const { return path_; }
  const FileContext& file() const { return file_; }

  bool is_object() const { return value_.is_object(); }
  bool is_string() const { return value_.is_string(); }
  // An object holding no keys but `allowed`.
  void expect_keys(const std::vector<std::string_view>& allowed) const {
    if (!value_.is_object()) fail("expected an object, got " + kind());
    for (const auto& [key, unused] : value_.items())
      if (std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
        std::string valid;
        for (std::string_view a : allowed) valid += (valid.empty() ? "" : ", ") + std::string(a);
        child(key).fail("unknown key (expected " + valid + ")");
      }
  }
  bool has(const std::string& key) const { return value_.contains(key); }
  JsonValue operator[](const std::string& key) const {
    if (!value_.contains(key)) fail("missing key '" + key + "'");
    return child(key);
  }
  std::vector<JsonValue> items() const {
    if (!value_.is_array()) fail("expected an array, got " + kind());
    std::vector<JsonValue> out;
    for (std::size_t i = 0; i < value_.size(); ++i)
      out.emplace_back(value_[i], path_ + "[" + std::to_string(i) + "]", file_);
    return out;
  }
  std::vector<JsonValue> nonempty_items() const {
    std::vector<JsonValue> out = items();
    if (out.empty()) fail("empty array");
    return out;
  }
  double number() const {
    if (!value_.is_number()) fail("expected a number, got " + kind());
    const double x = value_.get<double>();
    if (!std::isfinite(x)) fail("not a finite number");
    return x;
  }
  double positive() const {
    const double x = number();
    if (!(x > 0.0)) fail("must be > 0");
    return x;
  }
  Index label() const {
    if (!value_.is_number_integer()) fail("expected an integer label, got " + kind());
    const std::int64_t x = value_.get<std::int64_t>();
    if (x < 1 || x > kMaxIndex)
      fail("label " + std::to_string(x) + " is not in 1.." + std::to_string(kMaxIndex));
    return static_cast<Index>(x);
  }
  std::string text() const {
    if (!value_.is_string()) fail("expected a string, got " + kind());
    return value_.get<std::string>();
  }
  Vec3 vec3() const {
    const std::vector<JsonValue> x = items();
    if (x.size() != 3) fail("expected 3 numbers, got " + std::to_string(x.size()) + " values");
    return {x[0].number(), x[1].number(), x[2].number()};
  }
  Vec3 direction() const {
    const Vec3 d = vec3();
    if (!(d.norm() > 0.0)) fail("a zero vector is not a direction");
    return d;
  }
  std::vector<Index> labels() const {
    std::vector<Index> out;
    for (const JsonValue& x : nonempty_items()) out.push_back(x.label());
    return out;
  }

 private:
  JsonValue child(const std::string& key) const {
    return JsonValue(value_.at(key), path_.empty() ? key : path_ + "." + key, file_);
  }
  std::string kind() const {
    return value_.is_string() ? "a string '" + value_.get<std::string>() + "'"
                              : std::string(value_.type_name());
  }

  const json& value_;
  std::string path_;
  const FileContext& file_;
};

// Any InputError from `build` (a surface reader, a domain's checks) as one line prefixed by
// the file and the path of the value it came from.
template <class Build>
auto named(const JsonValue& at, Build&& build) {
  try {
    return build();
  } catch (const InputError& e) {
    at.fail(e.what());
  }
}

// The surface file named by a "file" value, relative to the domain file.
TriSurface read_surface_at(const JsonValue& file) {
  const std::string name = file.text();
  const fs::path path = file.file().dir / name;
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) file.fail("cannot open '" + name + "'");
  if (!is_surface_file(path))
    file.fail("'" + name + "' is not a surface file (expected .stl .off .obj or .ply)");
  return named(file, [&] { return read_surface(path); });
}

// ---- closed surfaces ----

std::unique_ptr<Domain> surfaces_domain(const JsonValue& list) {
  std::vector<LabelledSurface> surfaces;
  for (const JsonValue& s : list.nonempty_items()) {
    s.expect_keys({"file", "label", "name"});
    LabelledSurface ls;
    ls.surface = read_surface_at(s["file"]);
    ls.name = s.has("name") ? s["name"].text() : s["file"].text();
    if (s.has("label")) ls.label = s["label"].label();
    surfaces.push_back(std::move(ls));
  }
  return named(list, [&] { return std::make_unique<SurfaceDomain>(std::move(surfaces)); });
}

// ---- analytic solids ----

Rigid motion_of(const JsonValue& p) {
  Rigid m;
  if (p.has("rotate_zxz_deg")) {
    const Vec3 deg = p["rotate_zxz_deg"].vec3() * (std::numbers::pi / 180.0);
    m.rotation = euler_zxz(deg.x(), deg.y(), deg.z());
  }
  if (p.has("translate")) m.translation = p["translate"].vec3();
  return m;
}

Primitive primitive_of(const JsonValue& p) {
  if (!p.is_object() || !p.has("type")) p.fail("expected a primitive: an object with a 'type'");
  const std::string type = p["type"].text();
  const std::string name = p.has("name") ? p["name"].text() : type;
  // The keys of every primitive and its own.
  const auto keys = [&](std::initializer_list<std::string_view> own) {
    std::vector<std::string_view> all{"type", "name", "rotate_zxz_deg", "translate"};
    all.insert(all.end(), own.begin(), own.end());
    p.expect_keys(all);
  };
  Primitive out;
  if (type == "sphere") {
    keys({"centre", "radius"});
    out = sphere(p["centre"].vec3(), p["radius"].positive(), name);
  } else if (type == "box") {
    keys({"min", "max"});
    const Vec3 lo = p["min"].vec3(), hi = p["max"].vec3();
    if (!(lo.array() < hi.array()).all()) p["max"].fail("must be greater than min in x, y and z");
    out = box(lo, hi, name);
  } else if (type == "cylinder") {
    keys({"base", "top", "radius"});
    const Vec3 base = p["base"].vec3(), top = p["top"].vec3();
    if (base == top) p["top"].fail("equals base");
    out = cylinder(base, top, p["radius"].positive(), name);
  } else if (type == "torus") {
    keys({"centre", "axis", "major", "minor"});
    const double major = p["major"].positive(), minor = p["minor"].positive();
    if (!(minor < major)) p["minor"].fail("must be less than major");
    out = torus(p["centre"].vec3(), p["axis"].direction(), major, minor, name);
  } else if (type == "ellipsoid") {
    keys({"centre", "semi_axes"});
    const Vec3 semi = p["semi_axes"].vec3();
    if (!(semi.array() > 0.0).all()) p["semi_axes"].fail("must be > 0");
    out = ellipsoid(p["centre"].vec3(), semi, name);
  } else if (type == "half_space") {
    keys({"point", "normal"});
    out = half_space(p["point"].vec3(), p["normal"].direction(), name);
  } else {
    p["type"].fail("unknown primitive '" + type +
                   "' (expected sphere, box, cylinder, torus, ellipsoid or half_space)");
  }
  return moved(std::move(out), motion_of(p));
}

Solid solid_of(const JsonValue& s) {
  for (const char* op : {"union", "intersection", "difference"})
    if (s.is_object() && s.has(op)) {
      s.expect_keys({op});
      const std::vector<JsonValue> parts = s[op].nonempty_items();
      Solid out = solid_of(parts[0]);
      for (std::size_t i = 1; i < parts.size(); ++i) {
        const Solid next = solid_of(parts[i]);
        out = op[0] == 'u' ? (out | next) : op[0] == 'i' ? (out & next) : (out - next);
      }
      return out;
    }
  return primitive_of(s);
}

// ---- layers ----

Sheet plane_sheet_of(const JsonValue& plane, const Box3& box, const std::string& name, int axis) {
  plane.expect_keys({"point", "normal"});
  const Vec3 point = plane["point"].vec3(), normal = plane["normal"].direction();
  if (axis < 0) normal.cwiseAbs().maxCoeff(&axis);
  // A normal with less than this share along the axis leaves the plane nearly parallel to it:
  // its graph over the box's face would climb a million times its run.
  constexpr double kLeastAxisShare = 1e-6;
  if (std::abs(normal[axis]) < kLeastAxisShare * normal.norm())
    plane["normal"].fail("the plane is not a graph over the box's face across axis " +
                         std::string(1, "xyz"[axis]));
  return plane_sheet(box, axis, point, normal, name);
}

// A sheet: "file.off", {"file": ..., "name": ...}, {"height": z} or {"plane": {...}}; faults
// also take "axis".
Sheet sheet_of(const JsonValue& s, const Box3& box, bool fault) {
  if (s.is_string()) {
    if (fault) s.fail("a fault needs an object with \"file\" (or \"plane\") and \"axis\"");
    return Sheet{read_surface_at(s), 2, s.text()};
  }
  if (fault)
    s.expect_keys({"file", "plane", "axis", "name"});
  else
    s.expect_keys({"file", "plane", "height", "name"});
  int axis = fault ? -1 : 2;
  if (s.has("axis")) {
    const std::string a = s["axis"].text();
    if (a != "x" && a != "y" && a != "z") s["axis"].fail("expected \"x\", \"y\" or \"z\"");
    axis = a[0] - 'x';
  }
  const int given = s.has("file") + s.has("plane") + s.has("height");
  if (given != 1)
    s.fail(fault ? "expected one of \"file\" or \"plane\""
                 : "expected one of \"file\", \"plane\" or \"height\"");
  if (s.has("height")) {
    const double z = s["height"].number();
    return plane_sheet(box, 2, Vec3(0, 0, z), Vec3::UnitZ(),
                       s.has("name") ? s["name"].text() : s.path());
  }
  if (s.has("plane"))
    return plane_sheet_of(s["plane"], box, s.has("name") ? s["name"].text() : s.path(), axis);
  if (axis < 0) s.fail("missing key 'axis' (the axis the fault is a graph along)");
  return Sheet{read_surface_at(s["file"]), axis,
               s.has("name") ? s["name"].text() : s["file"].text()};
}

LayerBlock block_of(const JsonValue& b, const Box3& box) {
  LayerBlock block;
  if (b.has("horizons"))
    for (const JsonValue& h : b["horizons"].items())
      block.horizons.push_back(sheet_of(h, box, false));
  if (b.has("labels")) {
    block.labels = b["labels"].labels();
    if (block.labels.size() != block.horizons.size() + 1)
      b["labels"].fail(std::to_string(block.labels.size()) + " labels for " +
                       std::to_string(block.horizons.size()) + " horizons (expected one more)");
  } else {
    for (std::size_t i = 0; i <= block.horizons.size(); ++i)
      block.labels.push_back(static_cast<Index>(i + 1));
  }
  return block;
}

LayeredModel layered_model(const JsonValue& layers, const JsonValue& box_value) {
  box_value.expect_keys({"min", "max"});
  LayeredModel model;
  model.box = {box_value["min"].vec3(), box_value["max"].vec3()};
  if (!(model.box.lo.array() < model.box.hi.array()).all())
    box_value["max"].fail("must be greater than min in x, y and z");
  model.name = layers.file().name;
  if (layers.has("faults") || layers.has("blocks")) {
    layers.expect_keys({"faults", "blocks"});
    const std::vector<JsonValue> faults = layers["faults"].nonempty_items();
    if (faults.size() > 4) layers["faults"].fail("at most 4 faults");
    for (const JsonValue& f : faults) model.faults.push_back(sheet_of(f, model.box, true));
    const std::vector<JsonValue> blocks = layers["blocks"].items();
    if (blocks.size() != (std::size_t{1} << faults.size()))
      layers["blocks"].fail(std::to_string(blocks.size()) + " blocks for " +
                            std::to_string(faults.size()) + " faults (expected 2^faults)");
    for (const JsonValue& b : blocks) {
      b.expect_keys({"horizons", "labels"});
      model.blocks.push_back(block_of(b, model.box));
    }
  } else {
    layers.expect_keys({"horizons", "labels"});
    model.blocks.push_back(block_of(layers, model.box));
  }
  return model;
}

// ---- the file ----

// Every label a domain can produce must be ranked; labels are replaced by their ranks.
void rank_labels(const JsonValue& priority, const std::vector<Index>& order,
                 std::vector<Index>& labels) {
  for (Index& l : labels) {
    const Index r = rank_of(order, l);
    if (r == 0) priority.fail("label " + std::to_string(l) + " is not listed");
    l = r;
  }
}

std::unique_ptr<Domain> domain_of(const JsonValue& root) {
  root.expect_keys({"box", "surfaces", "layers", "solids", "materials", "priority"});
  const int kinds =
      root.has("surfaces") + root.has("layers") + root.has("solids") + root.has("materials");
  if (kinds != 1)
    root.fail("expected exactly one of \"surfaces\", \"layers\", \"solids\" or \"materials\"");
  if (root.has("box") && !root.has("layers")) root["box"].fail("only layered domains take a box");
  std::vector<Index> order;
  if (root.has("priority")) {
    if (root.has("surfaces"))
      root["priority"].fail("surface domains take no priority (a point on a surface is inside it)");
    const std::vector<JsonValue> items = root["priority"].nonempty_items();
    for (const JsonValue& x : items) {
      if (rank_of(order, x.label()) != 0)
        x.fail("label " + std::to_string(x.label()) + " is listed twice");
      order.push_back(x.label());
    }
  }
  const bool ranked = !order.empty();

  if (root.has("surfaces")) return surfaces_domain(root["surfaces"]);

  std::unique_ptr<Domain> domain;
  if (root.has("layers")) {
    LayeredModel model = layered_model(root["layers"], root["box"]);
    if (ranked)
      for (LayerBlock& b : model.blocks) rank_labels(root["priority"], order, b.labels);
    domain = std::make_unique<LayeredDomain>(std::move(model));  // its errors name the file
  } else if (root.has("solids")) {
    std::vector<Layer> solids;
    for (const JsonValue& s : root["solids"].nonempty_items()) {
      s.expect_keys({"solid", "label"});
      std::vector<Index> label{s["label"].label()};
      if (ranked) rank_labels(root["priority"], order, label);
      solids.push_back({solid_of(s["solid"]), label[0]});
    }
    domain = named(root["solids"],
                   [&] { return std::make_unique<AnalyticDomain>(layered_domain(solids)); });
  } else {
    const JsonValue list = root["materials"];
    std::vector<Primitive> primitives;
    for (const JsonValue& p : list.nonempty_items()) primitives.push_back(primitive_of(p));
    if (primitives.size() > static_cast<std::size_t>(AnalyticDomain::kMaxPrimitives))
      list.fail("at most " + std::to_string(AnalyticDomain::kMaxPrimitives) + " primitives");
    AnalyticDomain plain = named(list, [&] { return multi_material_domain(primitives); });
    if (!ranked) return std::make_unique<AnalyticDomain>(std::move(plain));
    // Overlaps that occur must be ranked; the others rank lowest, below every listed one.
    std::vector<Index> occurring = plain.regions();
    std::vector<Index> full = order;
    for (Index m = 1; m < (Index{1} << primitives.size()); ++m) {
      const bool listed = rank_of(order, m) != 0;
      if (!listed && std::binary_search(occurring.begin(), occurring.end(), m))
        root["priority"].fail("label " + std::to_string(m) + " is not listed");
      if (!listed) full.push_back(m);
    }
    order = full;
    std::vector<Index> table(std::size_t{1} << primitives.size(), 0);
    for (Index m = 1; m < static_cast<Index>(table.size()); ++m) table[m] = rank_of(order, m);
    domain = named(list, [&] {
      return std::make_unique<AnalyticDomain>(std::move(primitives), std::move(table));
    });
  }
  if (!ranked) return domain;
  return named(root["priority"], [&] { return prioritized(std::move(domain), order); });
}

}  // namespace

std::unique_ptr<Domain> read_domain_json(std::istream& in, const std::string& name,
                                         const fs::path& dir) {
  const FileContext file{name, dir};
  json root;
  try {
    root = json::parse(in);
  } catch (const json::parse_error& e) {
    // "[json.exception.parse_error.101] parse error at line 3, column 5: ..." -> "line 3, ..."
    std::string what = e.what();
    const std::size_t at = what.find(" at line ");
    throw InputError(file.name + ": invalid JSON" +
                     (at == std::string::npos ? ": " + what : what.substr(at)));
  }
  return domain_of(JsonValue(root, "", file));
}

std::unique_ptr<Domain> read_domain_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path.string() + ": cannot open");
  return read_domain_json(in, path.string(), path.parent_path());
}

}  // namespace volmesh
