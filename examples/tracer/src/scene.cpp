// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// scene.cpp — parser of the scene format described in scene.hpp.
#include "scene.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace pgt {

const char *mode_name(Mode m) {
    switch (m) {
    case Mode::MIS: return "mis";
    case Mode::BRDF: return "brdf";
    case Mode::LIGHT: return "light";
    }
    return "?";
}

Mode parse_mode(const std::string &s) {
    if (s == "mis") return Mode::MIS;
    if (s == "brdf") return Mode::BRDF;
    if (s == "light") return Mode::LIGHT;
    throw SceneError("mode must be mis, brdf or light, not '" + s + "'");
}

std::string printable(const std::string &text) {
    static const char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    auto byte_escape = [&](unsigned char c) { out += {'\\', 'x', hex[c >> 4], hex[c & 15]}; };
    const auto *s = reinterpret_cast<const unsigned char *>(text.data());
    const size_t n = text.size();
    for (size_t i = 0; i < n;) {
        unsigned char c = s[i];
        if (c >= 0x20 && c < 0x7f) {
            out += char(c);
            ++i;
            continue;
        }
        // A UTF-8 sequence (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF)?
        size_t len = c >= 0xc2 && c <= 0xdf ? 2 : c >= 0xe0 && c <= 0xef ? 3 : c >= 0xf0 && c <= 0xf4 ? 4 : 0;
        unsigned lo = c == 0xe0 ? 0xa0 : c == 0xf0 ? 0x90 : 0x80, hi = c == 0xed ? 0x9f : c == 0xf4 ? 0x8f : 0xbf;
        bool ok = len > 0 && i + len <= n && s[i + 1] >= lo && s[i + 1] <= hi;
        for (size_t k = 2; ok && k < len; ++k) ok = (s[i + k] & 0xc0) == 0x80;
        if (!ok) {  // a control character, DEL, or a byte that is not UTF-8
            byte_escape(c);
            ++i;
            continue;
        }
        unsigned cp = c & (0x7f >> len);
        for (size_t k = 1; k < len; ++k) cp = cp << 6 | (s[i + k] & 0x3f);
        if (cp <= 0x9f) {  // C1 controls (U+0080–U+009F): CSI is U+009B
            for (size_t k = 0; k < len; ++k) byte_escape(s[i + k]);
        } else if (cp == 0x200e || cp == 0x200f || (cp >= 0x202a && cp <= 0x202e) || (cp >= 0x2066 && cp <= 0x2069)) {
            out += "\\u{" + std::string{hex[cp >> 12], hex[(cp >> 8) & 15], hex[(cp >> 4) & 15], hex[cp & 15]} + "}";
        } else {
            out.append(text, i, len);
        }
        i += len;
    }
    return out;
}

int Scene::find_material(const std::string &name) const {
    if (material_index_.size() == materials.size()) {
        auto it = material_index_.find(name);
        return it == material_index_.end() ? -1 : it->second;
    }
    for (size_t i = 0; i < materials.size(); ++i)  // `materials` was changed directly
        if (materials[i].name == name) return static_cast<int>(i);
    return -1;
}

int Scene::add_material(Material m) {
    if (material_index_.size() != materials.size()) {  // re-index after direct changes
        material_index_.clear();
        for (size_t i = 0; i < materials.size(); ++i) material_index_.emplace(materials[i].name, int(i));
    }
    int i = static_cast<int>(materials.size());
    material_index_.emplace(m.name, i);
    materials.push_back(std::move(m));
    return i;
}

void Scene::set_material(const std::string &name, const pgloss_physical &p) {
    Material m;
    m.name = name;
    m.physical = p;
    pgloss_status st = pgloss_material_init(&m.ward, &p);
    if (st < 0) throw SceneError("material '" + name + "': " + pgloss_status_string(st));
    int i = find_material(name);
    if (i >= 0)
        materials[static_cast<size_t>(i)] = m;
    else
        add_material(m);
}

namespace {

// One line's fields, with the context to report errors.
class Line {
public:
    Line(std::string file, int number, std::vector<std::string> words)
        : file_(std::move(file)), number_(number) {
        for (size_t i = 1; i < words.size(); ++i) {
            const std::string &w = words[i];
            size_t eq = w.find('=');
            if (eq == std::string::npos) {
                positional_.push_back(w);
                continue;
            }
            std::string k = w.substr(0, eq);
            if (k.empty()) fail("", "a field has no name ('" + w + "')");
            if (kv_.count(k)) fail(k, "given twice");
            kv_[k] = w.substr(eq + 1);
        }
        keyword_ = words[0];
    }

    [[noreturn]] void fail(const std::string &field, const std::string &what) const {
        std::ostringstream o;
        o << file_ << ":" << number_ << ": " << keyword_;
        if (!field.empty()) o << ": field '" << field << "'";
        o << ": " << what;
        throw SceneError(o.str());
    }

    const std::string &keyword() const { return keyword_; }
    const std::vector<std::string> &positional() {
        positional_used_ = true;
        return positional_;
    }
    bool has(const std::string &k) const { return kv_.count(k) != 0; }

    std::string str(const std::string &k) {
        auto it = kv_.find(k);
        if (it == kv_.end()) fail(k, "missing");
        used_.push_back(k);
        return it->second;
    }
    std::string str(const std::string &k, const std::string &dflt) { return has(k) ? str(k) : dflt; }

    double num(const std::string &k) {
        std::string s = str(k);
        return to_num(k, s);
    }
    double num(const std::string &k, double dflt) { return has(k) ? num(k) : dflt; }

    // A number stored as float: in [lo, hi], or in (0, hi] when lo is 0 and positive is set.
    float real(const std::string &k, double lo, double hi, bool positive = false) {
        double v = num(k);
        if (!(positive ? v > lo : v >= lo) || !(v <= hi)) fail(k, range_text(lo, hi, positive, kv_.at(k)));
        return float(v);
    }
    float real(const std::string &k, double lo, double hi, bool positive, double dflt) {
        return has(k) ? real(k, lo, hi, positive) : float(dflt);
    }
    // A count: a whole number in [lo, hi].
    long long whole(const std::string &k, long long lo, long long hi) {
        double v = num(k);
        if (v != std::floor(v)) fail(k, "must be a whole number, got '" + kv_.at(k) + "'");
        if (!(v >= double(lo) && v <= double(hi)))
            fail(k, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got '" + kv_.at(k) + "'");
        return static_cast<long long>(v);
    }
    long long whole(const std::string &k, long long lo, long long hi, long long dflt) {
        return has(k) ? whole(k, lo, hi) : dflt;
    }

    // A point or a vector: three numbers, each within ±limits::coordinate.
    glm::vec3 vec(const std::string &k) {
        std::string s = str(k);
        std::vector<double> v = split_nums(k, s);
        if (v.size() != 3) fail(k, "expected x,y,z (three numbers), got '" + s + "'");
        for (double x : v)
            if (!(std::fabs(x) <= limits::coordinate))
                fail(k, "coordinates must be within ±" + short_num(limits::coordinate) + ", got '" + s + "'");
        return glm::vec3(float(v[0]), float(v[1]), float(v[2]));
    }
    glm::vec3 vec(const std::string &k, glm::vec3 dflt) { return has(k) ? vec(k) : dflt; }

    // A colour: one number (grey) or r,g,b, each in [lo, hi].
    glm::dvec3 color(const std::string &k, double lo, double hi) {
        std::string s = str(k);
        std::vector<double> v = split_nums(k, s);
        if (v.size() == 1) v.assign(3, v[0]);
        if (v.size() != 3) fail(k, "expected one number or r,g,b, got '" + s + "'");
        for (double x : v)
            if (!(x >= lo && x <= hi)) fail(k, range_text(lo, hi, false, s));
        return glm::dvec3(v[0], v[1], v[2]);
    }

    void finish() const {  // unknown fields and words are errors, so that typos are not silently ignored
        if (!positional_used_ && !positional_.empty())
            fail("", "unexpected word '" + positional_[0] + "' (fields are key=value)");
        for (auto &kv : kv_) {
            bool used = false;
            for (auto &u : used_) used = used || u == kv.first;
            if (!used) fail(kv.first, "unknown field for '" + keyword_ + "'");
        }
    }

private:
    static std::string short_num(double v) {
        std::ostringstream o;
        o << v;
        return o.str();
    }
    static std::string range_text(double lo, double hi, bool positive, const std::string &got) {
        return std::string("must be in ") + (positive ? "(" : "[") + short_num(lo) + ", " + short_num(hi) + "], got '" +
               got + "'";
    }
    double to_num(const std::string &k, const std::string &s) const {
        char *end = nullptr;
        double v = std::strtod(s.c_str(), &end);
        if (s.empty() || end != s.c_str() + s.size()) fail(k, "expected a number, got '" + s + "'");  // also "1\0x"
        if (!std::isfinite(v)) fail(k, "must be finite, got '" + s + "'");
        return v;
    }
    std::vector<double> split_nums(const std::string &k, const std::string &s) const {
        std::vector<double> out;
        std::stringstream ss(s);
        std::string item;
        while (std::getline(ss, item, ',')) out.push_back(to_num(k, item));
        return out;
    }

    std::string file_;
    int number_;
    std::string keyword_;
    std::vector<std::string> positional_;
    bool positional_used_ = false;
    std::map<std::string, std::string> kv_;
    std::vector<std::string> used_;
};

pgloss_normalization parse_norm(Line &l) {
    std::string n = l.str("norm", "ward");
    if (n == "ward") return PGLOSS_NORM_WARD;
    if (n == "ward-dur") return PGLOSS_NORM_WARD_DUR;
    if (n == "bounded") return PGLOSS_NORM_BOUNDED;
    l.fail("norm", "must be ward, ward-dur or bounded, not '" + n + "'");
}

void add_quad(Mesh &m, glm::vec3 c, glm::vec3 e1, glm::vec3 e2) {
    auto b = static_cast<unsigned>(m.vertices.size());
    m.vertices.insert(m.vertices.end(), {c, c + e1, c + e1 + e2, c + e2});
    m.faces.push_back({b, b + 1, b + 2});
    m.faces.push_back({b, b + 2, b + 3});
}

// The whole token as a number (strtod/strtoll would accept "3.9abc" as 3.9).
bool whole_double(const std::string &w, double &v) {
    if (w.empty()) return false;
    char *end = nullptr;
    v = std::strtod(w.c_str(), &end);
    return end == w.c_str() + w.size() && std::isfinite(v);  // not "1\0x" either
}
bool whole_long(const std::string &w, long long &v) {
    if (w.empty()) return false;
    char *end = nullptr;
    errno = 0;
    v = std::strtoll(w.c_str(), &end, 10);
    return end == w.c_str() + w.size() && errno == 0;
}

// An OBJ file as read: its vertices (in double, before scale and translate) and triangles.
struct ObjData {
    std::vector<glm::dvec3> vertices;
    std::vector<glm::uvec3> faces;
};

ObjData read_obj(Line &l, const std::string &path) {
    std::string all;
    try {
        all = read_text_file(path, limits::obj_bytes, "OBJ file");
    } catch (const SceneError &e) {
        l.fail("file", e.what());
    }
    std::istringstream in(all);
    ObjData d;
    std::string text;
    int ln = 0;
    long long n_vt = 0, n_vn = 0;  // texture coordinates and normals so far: their indices are checked too
    auto bad = [&](const std::string &what) { l.fail("file", path + ":" + std::to_string(ln) + ": " + what); };
    while (std::getline(in, text)) {
        ++ln;
        std::istringstream ss(text.substr(0, text.find('#')));
        std::string tag;
        ss >> tag;
        std::vector<std::string> w;
        for (std::string s; ss >> s;) w.push_back(s);
        if (tag == "v") {  // v x y z [w]
            glm::dvec3 x;
            if (w.size() < 3 || w.size() > 4) bad("a vertex is 'v x y z [w]'");
            for (int k = 0; k < 3; ++k)
                if (!whole_double(w[size_t(k)], x[k])) bad("bad vertex coordinate '" + w[size_t(k)] + "'");
            d.vertices.push_back(x);
        } else if (tag == "vt") {
            ++n_vt;
        } else if (tag == "vn") {
            ++n_vn;
        } else if (tag == "f") {  // f v | v/t | v/t/n | v//n …
            std::vector<unsigned> idx;
            for (const std::string &t : w) {
                std::vector<std::string> part;
                std::stringstream ps(t);
                for (std::string s; std::getline(ps, s, '/');) part.push_back(s);
                if (!t.empty() && t.back() == '/') part.push_back("");
                long long i = 0, extra = 0;
                bool ok = part.size() >= 1 && part.size() <= 3 && whole_long(part[0], i);
                for (size_t k = 1; ok && k < part.size(); ++k) {
                    if (k == 1 && part.size() == 3 && part[k].empty()) continue;  // v//n
                    ok = whole_long(part[k], extra);
                    // The tracer uses neither texture coordinates nor normals, but an index past
                    // what the file defines means a broken (or truncated) file: say so.
                    const long long have = k == 1 ? n_vt : n_vn;
                    const char *what = k == 1 ? "texture coordinate (vt)" : "normal (vn)";
                    if (ok && extra < 0) extra = have + extra + 1;
                    if (ok && (extra < 1 || extra > have))
                        bad("face vertex '" + t + "': " + what + " index " + part[k] + " out of range (" +
                            std::to_string(have) + " defined above)");
                }
                if (!ok) bad("bad face vertex '" + t + "' (v, v/t, v/t/n or v//n, whole numbers)");
                if (i < 0) i = static_cast<long long>(d.vertices.size()) + i + 1;
                if (i < 1 || i > static_cast<long long>(d.vertices.size()))
                    bad("face vertex '" + t + "': vertex index " + part[0] + " out of range (" +
                        std::to_string(d.vertices.size()) + " defined above)");
                idx.push_back(static_cast<unsigned>(i - 1));
            }
            if (idx.size() < 3) bad("face with < 3 vertices");
            for (size_t k = 1; k + 1 < idx.size(); ++k) d.faces.push_back({idx[0], idx[k], idx[k + 1]});
            if (d.faces.size() > limits::triangles) bad("more than " + std::to_string(limits::triangles) + " triangles");
        }
    }
    if (d.faces.empty()) l.fail("file", "'" + path + "' has no faces");
    return d;
}

// One `mesh` line's instance of an OBJ file: scaled and translated, every vertex within
// limits::coordinate (checked in double, before the float that Embree gets).
Mesh place_obj(Line &l, const std::string &path, const ObjData &d, int material, float scale, glm::vec3 translate) {
    Mesh m;
    m.material = material;
    m.label = "mesh:" + path;
    m.vertices.reserve(d.vertices.size());
    for (size_t i = 0; i < d.vertices.size(); ++i) {
        glm::dvec3 x = d.vertices[i] * double(scale) + glm::dvec3(translate);
        if (!(std::fabs(x.x) <= limits::coordinate && std::fabs(x.y) <= limits::coordinate &&
              std::fabs(x.z) <= limits::coordinate))
            l.fail("file", path + ": vertex " + std::to_string(i + 1) + " outside ±" +
                               std::to_string(long(limits::coordinate)) + " after scale and translate");
        m.vertices.push_back(glm::vec3(x));
    }
    m.faces = d.faces;
    return m;
}

std::vector<std::string> tokenize(const std::string &line) {
    std::string s = line.substr(0, line.find('#'));
    std::istringstream ss(s);
    std::vector<std::string> w;
    std::string t;
    while (ss >> t) w.push_back(t);
    return w;
}

}  // namespace

Scene parse_scene(const std::string &text, const std::string &file, const std::string &base_dir) {
    Scene sc;
    sc.path = file;
    std::istringstream in(text);
    std::string raw;
    int number = 0;
    bool have_camera = false;
    std::map<std::string, ObjData> objs;  // OBJ files read so far, by path
    size_t triangles = 0;                 // in `mesh` instances so far
    while (std::getline(in, raw)) {
        ++number;
        std::vector<std::string> words = tokenize(raw);
        if (words.empty()) continue;
        Line l(file, number, words);
        const std::string &kw = l.keyword();
        auto material_ref = [&](const std::string &field) {
            std::string n = l.str(field);
            int i = sc.find_material(n);
            if (i < 0) l.fail(field, "no material named '" + n + "' defined above");
            return i;
        };
        if (kw == "image") {
            sc.settings.width = int(l.whole("width", 1, limits::image_side));
            sc.settings.height = int(l.whole("height", 1, limits::image_side));
            if (static_cast<long long>(sc.settings.width) * sc.settings.height > limits::pixels)
                l.fail("height", "width × height must be at most " + std::to_string(limits::pixels) + " pixels");
        } else if (kw == "camera") {
            sc.camera.position = l.vec("position");
            sc.camera.look_at = l.vec("look_at");
            sc.camera.up = l.vec("up", {0, 1, 0});
            sc.camera.fov_deg = l.real("fov", 0, 179, true, 45);
            if (!(sc.camera.fov_deg < 179)) l.fail("fov", "must be in (0, 179) degrees");
            std::string why = camera_basis_problem(sc.camera);
            if (!why.empty()) l.fail(why.rfind("up", 0) == 0 ? "up" : "look_at", why);
            have_camera = true;
        } else if (kw == "render") {
            sc.settings.spp = int(l.whole("spp", 1, limits::spp, sc.settings.spp));
            sc.settings.max_depth = int(l.whole("max_depth", 1, limits::max_depth, sc.settings.max_depth));
            sc.settings.seed = static_cast<unsigned>(l.whole("seed", 0, limits::seed, sc.settings.seed));
            if (l.has("mode")) {
                try {
                    sc.settings.mode = parse_mode(l.str("mode"));
                } catch (const SceneError &e) {
                    l.fail("mode", e.what());
                }
            }
        } else if (kw == "tonemap") {
            sc.tonemap.exposure = l.real("exposure", 0, limits::tonemap, true, 1);
            sc.tonemap.limit = l.real("limit", 0, limits::tonemap, true, 1);
            sc.tonemap.sharpness = l.real("sharpness", 0, limits::sharpness, true, 2);
        } else if (kw == "material") {
            if (l.positional().empty()) l.fail("", "needs a name: material NAME KIND key=value…");
            std::string name = l.positional()[0];
            std::string kind = l.positional().size() > 1 ? l.positional()[1] : "";
            if (l.positional().size() > 2) l.fail("", "unexpected word '" + l.positional()[2] + "'");
            if (sc.find_material(name) >= 0) l.fail("", "material '" + name + "' defined twice");
            Material m;
            m.name = name;
            pgloss_physical p{};
            pgloss_status st = PGLOSS_OK;
            std::string field;
            if (kind.empty() && l.has("diffuse")) {
                glm::dvec3 rd = l.color("diffuse", -DBL_MAX, DBL_MAX);
                p = pgloss_physical{{rd.x, rd.y, rd.z}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD};
                field = "diffuse";
            } else if (kind == "physical") {
                glm::dvec3 rd = l.color("rho_d", -DBL_MAX, DBL_MAX);
                double rs = l.num("rho_s"), a = l.num("alpha");
                double ay = l.num("alpha_y", a);
                p = pgloss_physical{{rd.x, rd.y, rd.z}, rs, a, ay, parse_norm(l)};
                field = "rho_d/rho_s/alpha";
            } else if (kind == "perceptual") {
                pgloss_perceptual q{l.num("L"), l.num("a", 0), l.num("b", 0), l.num("c"), l.num("d")};
                pgloss_normalization n = parse_norm(l);
                st = pgloss_physical_from_perceptual(&q, n, &p);
                if (st < 0) l.fail("L/a/b/c/d", pgloss_status_string(st));
                st = pgloss_check_perceptual(&q);
                if (st < 0) l.fail("L/a/b/c/d", std::string("outside the paper's model: ") + pgloss_status_string(st));
                field = "L/a/b/c/d";
            } else if (kind == "checker") {
                m.checker = true;
                m.check_a = material_ref("a");
                m.check_b = material_ref("b");
                m.check_size = l.real("size", limits::checker_min, limits::coordinate);
                m.check_offset = l.vec("offset", glm::vec3(0));
                if (sc.materials[size_t(m.check_a)].checker || sc.materials[size_t(m.check_b)].checker)
                    l.fail("a/b", "a checker's cells must be plain materials");
            } else {
                l.fail("", "material kind must be physical, perceptual, checker (or diffuse=…), not '" + kind + "'");
            }
            if (!m.checker) {
                m.physical = p;
                st = pgloss_material_init(&m.ward, &p);
                if (st < 0) l.fail(field, pgloss_status_string(st));
            }
            sc.add_material(std::move(m));
        } else if (kw == "sphere") {
            Sphere s{l.vec("center"), l.real("radius", 0, limits::coordinate, true), material_ref("material")};
            sc.spheres.push_back(s);
        } else if (kw == "box") {
            glm::vec3 a = l.vec("min"), b = l.vec("max");
            if (!(a.x < b.x && a.y < b.y && a.z < b.z)) l.fail("max", "must exceed min in x, y and z");
            Mesh m;
            m.material = material_ref("material");
            m.label = "box";
            glm::vec3 d = b - a;
            glm::vec3 ex(d.x, 0, 0), ey(0, d.y, 0), ez(0, 0, d.z);
            add_quad(m, a, ey, ex);                 // z = min
            add_quad(m, a + ez, ex, ey);            // z = max
            add_quad(m, a, ez, ey);                 // x = min
            add_quad(m, a + ex, ey, ez);            // x = max
            add_quad(m, a, ex, ez);                 // y = min
            add_quad(m, a + ey, ez, ex);            // y = max
            sc.meshes.push_back(std::move(m));
        } else if (kw == "quad") {
            Mesh m;
            m.material = material_ref("material");
            m.label = "quad";
            add_quad(m, l.vec("corner"), l.vec("edge1"), l.vec("edge2"));
            sc.meshes.push_back(std::move(m));
        } else if (kw == "mesh") {
            std::string f = l.str("file");
            std::string path = (!f.empty() && f[0] == '/') ? f : base_dir + "/" + f;
            int mat = material_ref("material");
            float scale = l.real("scale", 0, limits::coordinate, true, 1);
            glm::vec3 translate = l.vec("translate", glm::vec3(0));
            // Each file is read once per scene: a scene may instance one model many times.
            auto it = objs.find(path);
            if (it == objs.end()) it = objs.emplace(path, read_obj(l, path)).first;
            if (triangles + it->second.faces.size() > limits::triangles)
                l.fail("file", "the scene would have more than " + std::to_string(limits::triangles) + " triangles");
            triangles += it->second.faces.size();
            sc.meshes.push_back(place_obj(l, path, it->second, mat, scale, translate));
        } else if (kw == "light") {
            AreaLight a;
            a.corner = l.vec("corner");
            a.edge1 = l.vec("edge1");
            a.edge2 = l.vec("edge2");
            a.radiance = glm::vec3(l.color("radiance", 0, limits::radiance));
            std::string e = l.str("emission", "cosine");
            if (e != "cosine" && e != "isotropic") l.fail("emission", "must be cosine or isotropic, not '" + e + "'");
            a.isotropic = e == "isotropic";
            // In double: |edge1 × edge2| of long edges overflows nothing, and the test for
            // parallel edges is relative to their lengths.
            glm::dvec3 e1(a.edge1), e2(a.edge2), n = glm::cross(e1, e2);
            double area = glm::length(n);
            if (!(area > 1e-6 * glm::length(e1) * glm::length(e2)) || !(area > 0))
                l.fail("edge2", "the edges are parallel or zero (no area)");
            a.area = float(area);
            a.normal = glm::vec3(n / area);
            sc.lights.push_back(a);
        } else if (kw == "environment") {
            glm::dvec3 r = l.color("radiance", 0, limits::radiance);
            sc.has_environment = true;
            sc.environment = glm::vec3(r);
        } else {
            l.fail("", "unknown keyword (image, camera, render, tonemap, material, sphere, box, quad, "
                       "mesh, light, environment)");
        }
        l.finish();
    }
    if (!have_camera) throw SceneError(file + ": no 'camera' line");
    if (sc.lights.empty() && !sc.has_environment)
        throw SceneError(file + ": no light (need a 'light' or an 'environment' line)");
    return sc;
}

std::string read_text_file(const std::string &path, unsigned long long max_bytes, const std::string &what) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::file_status st = fs::status(path, ec);
    if (st.type() == fs::file_type::not_found) throw SceneError(path + ": cannot open " + what + " (no such file)");
    if (ec) throw SceneError(path + ": cannot open " + what + ": " + ec.message());  // e.g. "Permission denied"
    if (!fs::is_regular_file(st)) throw SceneError(path + ": " + what + " is not a regular file");
    auto size = fs::file_size(path, ec);
    if (ec) throw SceneError(path + ": cannot read " + what + ": " + ec.message());
    if (size > max_bytes)
        throw SceneError(path + ": " + what + " is larger than " + std::to_string(max_bytes >> 20) + " MiB");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw SceneError(path + ": cannot open " + what + (errno ? std::string(": ") + std::strerror(errno) : ""));
    std::string text(static_cast<size_t>(size), '\0');
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<size_t>(in.gcount()));  // a file that shrank meanwhile reads short
    return text;
}

std::string camera_basis_problem(const Camera &c) {
    glm::dvec3 f = glm::dvec3(c.look_at) - glm::dvec3(c.position), up(c.up);
    if (!(glm::length(f) > 0)) return "look_at equals position";
    if (!(glm::length(up) > 0)) return "up must not be the zero vector";
    // sin of the angle between the view direction and up: below ~1e-3 rad the image's
    // horizontal axis (f × up) is undefined or noise.
    double s = glm::length(glm::cross(f, up)) / (glm::length(f) * glm::length(up));
    if (!(s > 1e-3))
        return "up is parallel to the view direction (position → look_at); give an up at an angle to it, "
               "e.g. up=0,0,-1 for a camera looking straight down";
    return "";
}

Scene load_scene(const std::string &path) {
    std::string text = read_text_file(path, limits::scene_bytes, "scene file");
    std::string dir = ".";
    size_t slash = path.find_last_of('/');
    if (slash != std::string::npos) dir = path.substr(0, slash);
    return parse_scene(text, path, dir);
}

}  // namespace pgt
