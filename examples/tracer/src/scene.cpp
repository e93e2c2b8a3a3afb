// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// scene.cpp — parser of the scene format described in scene.hpp.
#include "scene.hpp"

#include <cmath>
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

int Scene::find_material(const std::string &name) const {
    for (size_t i = 0; i < materials.size(); ++i)
        if (materials[i].name == name) return static_cast<int>(i);
    return -1;
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
        materials.push_back(m);
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
    const std::vector<std::string> &positional() const { return positional_; }
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

    glm::vec3 vec(const std::string &k) {
        std::string s = str(k);
        std::vector<double> v = split_nums(k, s);
        if (v.size() != 3) fail(k, "expected x,y,z (three numbers), got '" + s + "'");
        return glm::vec3(float(v[0]), float(v[1]), float(v[2]));
    }
    glm::vec3 vec(const std::string &k, glm::vec3 dflt) { return has(k) ? vec(k) : dflt; }

    // A colour: one number (grey) or r,g,b.
    glm::dvec3 color(const std::string &k) {
        std::string s = str(k);
        std::vector<double> v = split_nums(k, s);
        if (v.size() == 1) return glm::dvec3(v[0]);
        if (v.size() != 3) fail(k, "expected one number or r,g,b, got '" + s + "'");
        return glm::dvec3(v[0], v[1], v[2]);
    }

    void finish() const {  // unknown fields are errors, so that typos are not silently ignored
        for (auto &kv : kv_) {
            bool used = false;
            for (auto &u : used_) used = used || u == kv.first;
            if (!used) fail(kv.first, "unknown field for '" + keyword_ + "'");
        }
    }

private:
    double to_num(const std::string &k, const std::string &s) const {
        char *end = nullptr;
        double v = std::strtod(s.c_str(), &end);
        if (s.empty() || *end != '\0') fail(k, "expected a number, got '" + s + "'");
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

Mesh load_obj(Line &l, const std::string &path, int material, float scale, glm::vec3 translate) {
    std::ifstream in(path);
    if (!in) l.fail("file", "cannot open '" + path + "'");
    Mesh m;
    m.material = material;
    m.label = "mesh:" + path;
    std::string text;
    int ln = 0;
    while (std::getline(in, text)) {
        ++ln;
        std::istringstream ss(text);
        std::string tag;
        ss >> tag;
        if (tag == "v") {
            glm::vec3 p;
            if (!(ss >> p.x >> p.y >> p.z))
                l.fail("file", path + ":" + std::to_string(ln) + ": bad vertex");
            m.vertices.push_back(p * scale + translate);
        } else if (tag == "f") {
            std::vector<unsigned> idx;
            std::string w;
            while (ss >> w) {
                long i = std::strtol(w.c_str(), nullptr, 10);  // "i", "i/t", "i/t/n", "i//n"
                if (i < 0) i = static_cast<long>(m.vertices.size()) + i + 1;
                if (i < 1 || i > static_cast<long>(m.vertices.size()))
                    l.fail("file", path + ":" + std::to_string(ln) + ": face index out of range");
                idx.push_back(static_cast<unsigned>(i - 1));
            }
            if (idx.size() < 3) l.fail("file", path + ":" + std::to_string(ln) + ": face with < 3 vertices");
            for (size_t k = 1; k + 1 < idx.size(); ++k) m.faces.push_back({idx[0], idx[k], idx[k + 1]});
        }
    }
    if (m.faces.empty()) l.fail("file", "'" + path + "' has no faces");
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
        auto positive = [&](const std::string &field, double v) {
            if (!(v > 0)) l.fail(field, "must be > 0");
            return v;
        };
        if (kw == "image") {
            sc.settings.width = static_cast<int>(positive("width", l.num("width")));
            sc.settings.height = static_cast<int>(positive("height", l.num("height")));
        } else if (kw == "camera") {
            sc.camera.position = l.vec("position");
            sc.camera.look_at = l.vec("look_at");
            sc.camera.up = l.vec("up", {0, 1, 0});
            sc.camera.fov_deg = float(l.num("fov", 45));
            if (!(sc.camera.fov_deg > 0 && sc.camera.fov_deg < 179)) l.fail("fov", "must be in (0, 179) degrees");
            if (glm::length(sc.camera.look_at - sc.camera.position) <= 0)
                l.fail("look_at", "equals position");
            have_camera = true;
        } else if (kw == "render") {
            sc.settings.spp = static_cast<int>(positive("spp", l.num("spp", sc.settings.spp)));
            sc.settings.max_depth = static_cast<int>(positive("max_depth", l.num("max_depth", sc.settings.max_depth)));
            sc.settings.seed = static_cast<unsigned>(l.num("seed", sc.settings.seed));
            if (l.has("mode")) {
                try {
                    sc.settings.mode = parse_mode(l.str("mode"));
                } catch (const SceneError &e) {
                    l.fail("mode", e.what());
                }
            }
        } else if (kw == "tonemap") {
            sc.tonemap.exposure = float(positive("exposure", l.num("exposure", 1)));
            sc.tonemap.limit = float(positive("limit", l.num("limit", 1)));
            sc.tonemap.sharpness = float(positive("sharpness", l.num("sharpness", 2)));
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
                glm::dvec3 rd = l.color("diffuse");
                p = pgloss_physical{{rd.x, rd.y, rd.z}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD};
                field = "diffuse";
            } else if (kind == "physical") {
                glm::dvec3 rd = l.color("rho_d");
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
                m.check_size = float(positive("size", l.num("size")));
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
            sc.materials.push_back(m);
        } else if (kw == "sphere") {
            Sphere s{l.vec("center"), float(positive("radius", l.num("radius"))), material_ref("material")};
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
            float scale = float(positive("scale", l.num("scale", 1)));
            sc.meshes.push_back(load_obj(l, path, mat, scale, l.vec("translate", glm::vec3(0))));
        } else if (kw == "light") {
            AreaLight a;
            a.corner = l.vec("corner");
            a.edge1 = l.vec("edge1");
            a.edge2 = l.vec("edge2");
            glm::dvec3 r = l.color("radiance");
            if (r.x < 0 || r.y < 0 || r.z < 0) l.fail("radiance", "must be >= 0");
            a.radiance = glm::vec3(r);
            std::string e = l.str("emission", "cosine");
            if (e != "cosine" && e != "isotropic") l.fail("emission", "must be cosine or isotropic, not '" + e + "'");
            a.isotropic = e == "isotropic";
            glm::vec3 n = glm::cross(a.edge1, a.edge2);
            a.area = glm::length(n);
            if (!(a.area > 0)) l.fail("edge2", "the edges are parallel (zero area)");
            a.normal = n / a.area;
            sc.lights.push_back(a);
        } else if (kw == "environment") {
            glm::dvec3 r = l.color("radiance");
            if (r.x < 0 || r.y < 0 || r.z < 0) l.fail("radiance", "must be >= 0");
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

Scene load_scene(const std::string &path) {
    std::ifstream in(path);
    if (!in) throw SceneError(path + ": cannot open scene file");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string dir = ".";
    size_t slash = path.find_last_of('/');
    if (slash != std::string::npos) dir = path.substr(0, slash);
    return parse_scene(ss.str(), path, dir);
}

}  // namespace pgt
