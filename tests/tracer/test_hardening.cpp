// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// Bad input and faults in the tracer: every number is checked where it is parsed, a sample that
// is not finite fails the render instead of being dropped, a cancelled render keeps what it
// has, outputs are written whole or not at all. Each case here crashed, hung, returned an
// empty reason or rendered a silent black image before.
#include "image.hpp"
#include "render.hpp"
#include "scene.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cfloat>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;
using namespace std::string_literals;

const std::string kHead = "camera position=0,0,3 look_at=0,0,0\nenvironment radiance=1\nmaterial m diffuse=0.5\n";

std::string error_of(const std::string &text, const std::string &dir = ".") {
    try {
        pgt::parse_scene(text, "bad.scene", dir);
    } catch (const pgt::SceneError &e) {
        return e.what();
    }
    return "";
}

TEST(Hardening, CameraBasisMustBeProper) {
    // Looking straight down with the default up: the image's horizontal axis is undefined.
    EXPECT_EQ(error_of("camera position=0,2,0 look_at=0,0.5,0\n"),
              "bad.scene:1: camera: field 'up': up is parallel to the view direction (position → look_at); "
              "give an up at an angle to it, e.g. up=0,0,-1 for a camera looking straight down");
    EXPECT_EQ(error_of("camera position=0,2,0 look_at=0,0.5,0 up=0,0,0\n"),
              "bad.scene:1: camera: field 'up': up must not be the zero vector");
    EXPECT_EQ(error_of("camera position=1,1,1 look_at=1,1,1\n"),
              "bad.scene:1: camera: field 'look_at': look_at equals position");
    EXPECT_EQ(error_of("camera position=0,2,0 look_at=0,0.5,0 up=0,0,-1\nenvironment radiance=1\n"), "");
}

TEST(Hardening, NumbersOutsideFloatOrTheDomainAreRefused) {
    EXPECT_EQ(error_of(kHead + "sphere center=0,0,0 radius=1e300 material=m\n"),
              "bad.scene:4: sphere: field 'radius': must be in (0, 1e+07], got '1e300'");
    EXPECT_EQ(error_of(kHead + "sphere center=0,1e39,0 radius=1 material=m\n"),
              "bad.scene:4: sphere: field 'center': coordinates must be within ±1e+07, got '0,1e39,0'");
    EXPECT_EQ(error_of("camera position=0,0,1e39 look_at=0,0,0\n"),
              "bad.scene:1: camera: field 'position': coordinates must be within ±1e+07, got '0,0,1e39'");
    EXPECT_EQ(error_of(kHead + "light corner=0,1,0 edge1=1,0,0 edge2=0,0,1 radiance=1e39\n"),
              "bad.scene:4: light: field 'radiance': must be in [0, 1e+12], got '1e39'");
    EXPECT_EQ(error_of(kHead + "light corner=0,1,0 edge1=1e20,0,0 edge2=0,0,1e20 radiance=1\n"),
              "bad.scene:4: light: field 'edge1': coordinates must be within ±1e+07, got '1e20,0,0'");
    EXPECT_EQ(error_of(kHead + "light corner=0,1,0 edge1=1,0,0 edge2=2,0,0 radiance=1\n"),
              "bad.scene:4: light: field 'edge2': the edges are parallel or zero (no area)");
    EXPECT_EQ(error_of(kHead + "tonemap exposure=1e39\n"),
              "bad.scene:4: tonemap: field 'exposure': must be in (0, 1e+12], got '1e39'");
    EXPECT_EQ(error_of(kHead + "material c checker a=m b=m size=1e-30\n"),
              "bad.scene:4: material: field 'size': must be in [1e-06, 1e+07], got '1e-30'");
}

TEST(Hardening, CountsAreWholeNumbersInRange) {
    EXPECT_EQ(error_of(kHead + "image width=1e10 height=10\n"),
              "bad.scene:4: image: field 'width': must be in [1, 32768], got '1e10'");
    EXPECT_EQ(error_of(kHead + "image width=0.5 height=10\n"),
              "bad.scene:4: image: field 'width': must be a whole number, got '0.5'");
    EXPECT_EQ(error_of(kHead + "image width=32768 height=32768\n"),
              "bad.scene:4: image: field 'height': width × height must be at most 67108864 pixels");
    EXPECT_EQ(error_of(kHead + "render spp=0.5\n"), "bad.scene:4: render: field 'spp': must be a whole number, got '0.5'");
    EXPECT_EQ(error_of(kHead + "render spp=1e10\n"),
              "bad.scene:4: render: field 'spp': must be in [1, 16777216], got '1e10'");
    EXPECT_EQ(error_of(kHead + "render max_depth=1e10\n"),
              "bad.scene:4: render: field 'max_depth': must be in [1, 1024], got '1e10'");
    EXPECT_EQ(error_of(kHead + "render seed=-1\n"), "bad.scene:4: render: field 'seed': must be in [0, 4294967295], got '-1'");
}

class ObjFile : public ::testing::Test {
protected:
    fs::path dir = fs::path(PGLOSS_TEST_OUT) / "obj";
    void SetUp() override { fs::create_directories(dir); }
    std::string with(const std::string &obj, const std::string &extra = "") {
        std::ofstream(dir / "t.obj") << obj;
        return error_of(kHead + "mesh file=t.obj material=m" + extra + "\n", dir.string());
    }
};

TEST_F(ObjFile, MalformedNumbersAreErrors) {
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::string where = "bad.scene:4: mesh: field 'file': " + (dir / "t.obj").string();
    EXPECT_EQ(with(tri + "f 1x 2abc 3.9\n"), where + ":4: bad face vertex '1x' (v, v/t, v/t/n or v//n, whole numbers)");
    EXPECT_EQ(with(tri + "f 1 2 3.9\n"), where + ":4: bad face vertex '3.9' (v, v/t, v/t/n or v//n, whole numbers)");
    EXPECT_EQ(with("v 0 0 0abc\n"), where + ":1: bad vertex coordinate '0abc'");
    EXPECT_EQ(with("v 0 0\n"), where + ":1: a vertex is 'v x y z [w]'");
    EXPECT_EQ(with(tri + "f 1 2 4\n"), where + ":4: face vertex '4': vertex index 4 out of range (3 defined above)");
    // A vertex that overflows float after the scene's scale.
    EXPECT_EQ(with("v 1e38 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", " scale=10"),
              "bad.scene:4: mesh: field 'file': " + (dir / "t.obj").string() +
                  ": vertex 1 outside ±10000000 after scale and translate");
    // The usual forms stay accepted: v, v/t, v/t/n, v//n, negative (relative) indices, comments.
    EXPECT_EQ(with(tri + "vt 0 0\nvn 0 0 1\nf 1/1/1 2//1 -1/1 # a comment\n"), "");
}

TEST_F(ObjFile, TextureAndNormalIndicesOutOfRangeAreErrors) {
    // The tracer reads neither vt nor vn, but an index past them means a broken file (a
    // truncated export, indices of another file): it was silently accepted.
    const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    const std::string where = "bad.scene:4: mesh: field 'file': " + (dir / "t.obj").string();
    EXPECT_EQ(with(tri + "vt 0 0\nf 1/1 2/2 3/1\n"),
              where + ":5: face vertex '2/2': texture coordinate (vt) index 2 out of range (1 defined above)");
    EXPECT_EQ(with(tri + "f 1/1 2/1 3/1\n"),
              where + ":4: face vertex '1/1': texture coordinate (vt) index 1 out of range (0 defined above)");
    EXPECT_EQ(with(tri + "vn 0 0 1\nf 1//1 2//1 3//7\n"),
              where + ":5: face vertex '3//7': normal (vn) index 7 out of range (1 defined above)");
    EXPECT_EQ(with(tri + "vt 0 0\nvn 0 0 1\nf 1/1/1 2/1/-2 3/1/1\n"),
              where + ":6: face vertex '2/1/-2': normal (vn) index -2 out of range (1 defined above)");
    // Defined after the face that uses them: also out of range (OBJ indices refer backwards).
    EXPECT_EQ(with(tri + "f 1/1 2/1 3/1\nvt 0 0\n"),
              where + ":4: face vertex '1/1': texture coordinate (vt) index 1 out of range (0 defined above)");
    EXPECT_EQ(with(tri + "vt 0 0\nvt 1 0\nvn 0 0 1\nf 1/-1/1 2/-2/-1 3/2/1\n"), "");
}

TEST_F(ObjFile, OneFileInstancedManyTimes) {
    // Each `mesh` line is its own instance (scale, translate) of the file, which is read once.
    std::ofstream(dir / "t.obj") << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    std::string text = kHead;
    const int n = 500;
    for (int i = 0; i < n; ++i)
        text += "mesh file=t.obj material=m scale=2 translate=" + std::to_string(i) + ",0,0\n";
    pgt::Scene sc = pgt::parse_scene(text, "t.scene", dir.string());
    ASSERT_EQ(sc.meshes.size(), size_t(n));
    for (int i = 0; i < n; ++i) {
        const pgt::Mesh &m = sc.meshes[size_t(i)];
        ASSERT_EQ(m.faces.size(), 1u);
        EXPECT_EQ(m.vertices[1], glm::vec3(float(i) + 2.0f, 0.0f, 0.0f));
        EXPECT_EQ(m.vertices[2], glm::vec3(float(i), 2.0f, 0.0f));
    }
    // An instance outside the coordinate limit is refused though the file was read fine before.
    EXPECT_EQ(error_of(kHead + "mesh file=t.obj material=m\nmesh file=t.obj material=m scale=1e7 translate=1,0,0\n",
                       dir.string()),
              "bad.scene:5: mesh: field 'file': " + (dir / "t.obj").string() +
                  ": vertex 2 outside ±10000000 after scale and translate");
}

TEST(Hardening, WordsWithoutAFieldNameAreErrors) {
    // Only `material NAME KIND` takes bare words; elsewhere a stray word is a typo, not ignored.
    EXPECT_EQ(error_of(kHead + "sphere center=0,0,0 radius=1 material=m shiny\n"),
              "bad.scene:4: sphere: unexpected word 'shiny' (fields are key=value)");
    EXPECT_EQ(error_of(kHead + "render 16\n"), "bad.scene:4: render: unexpected word '16' (fields are key=value)");
    EXPECT_EQ(error_of(kHead + "material n physical extra rho_d=0.1 rho_s=0 alpha=0.1\n"),
              "bad.scene:4: material: unexpected word 'extra'");
}

TEST_F(ObjFile, OnlyBoundedRegularFilesAreRead) {
    // /dev/zero is one endless line: refused before a byte is read.
    EXPECT_EQ(error_of(kHead + "mesh file=/dev/zero material=m\n"),
              "bad.scene:4: mesh: field 'file': /dev/zero: OBJ file is not a regular file");
    EXPECT_EQ(error_of(kHead + "mesh file=/nonexistent.obj material=m\n"),
              "bad.scene:4: mesh: field 'file': /nonexistent.obj: cannot open OBJ file (no such file)");
    try {
        pgt::load_scene("/dev/zero");
        ADD_FAILURE() << "load_scene(/dev/zero) returned";
    } catch (const pgt::SceneError &e) {
        EXPECT_STREQ(e.what(), "/dev/zero: scene file is not a regular file");
    }
}

TEST(Hardening, SceneBytesInMessagesAreEscaped) {
    // An ANSI escape sequence in a scene reached the terminal; a NUL cut the message short.
    std::string esc = error_of(kHead + "sphere center=0,0,0 radius=\x1b[2J\x1b[31mred material=m\n");
    EXPECT_EQ(esc, "bad.scene:4: sphere: field 'radius': expected a number, got '\\x1b[2J\\x1b[31mred'");
    std::string nul = error_of(kHead + "sph\0ere radius=1\n"s);
    EXPECT_EQ(nul, "bad.scene:4: sph\\x00ere: unknown keyword (image, camera, render, tonemap, material, sphere, box, "
                   "quad, mesh, light, environment)");
    // A number with a NUL inside was read up to the NUL ("1\0x" as 1).
    EXPECT_EQ(error_of(kHead + "sphere center=0,0,0 radius=1\0x material=m\n"s),
              "bad.scene:4: sphere: field 'radius': expected a number, got '1\\x00x'");
    // OBJ lines too (their bytes reach the message through the scene's error).
    fs::path dir = fs::path(PGLOSS_TEST_OUT) / "obj-escape";
    fs::create_directories(dir);
    std::ofstream(dir / "t.obj") << "v 0 0 \x1b]0;title\x07\n";
    EXPECT_EQ(error_of(kHead + "mesh file=t.obj material=m\n", dir.string()),
              "bad.scene:4: mesh: field 'file': " + (dir / "t.obj").string() +
                  ":1: bad vertex coordinate '\\x1b]0;title\\x07'");
}

TEST(Hardening, PrintableEscapesControlsAndBrokenUtf8Only) {
    EXPECT_EQ(pgt::printable("plain ± × ρ é 日本 🙂"), "plain ± × ρ é 日本 🙂");     // UTF-8 stays
    EXPECT_EQ(pgt::printable("a\0b\tc\nd\x7f"s), "a\\x00b\\x09c\\x0ad\\x7f");  // C0, DEL
    EXPECT_EQ(pgt::printable("\xc2\x9b" "2J"), "\\xc2\\x9b2J");                       // C1 CSI (U+009B)
    EXPECT_EQ(pgt::printable("\xff\xc0\xaf \xe2\x82 \xed\xa0\x80"),                    // not UTF-8
              "\\xff\\xc0\\xaf \\xe2\\x82 \\xed\\xa0\\x80");
    EXPECT_EQ(pgt::printable("abc\xe2\x80\xaexyz"), "abc\\u{202e}xyz");                // bidi override
    const std::string once = pgt::printable("\x1b[31m \xff \xe2\x80\xae ρ");
    EXPECT_EQ(pgt::printable(once), once);  // idempotent: a quoted message is not escaped twice
}

TEST(Hardening, ManyMaterialsParseInLinearTime) {
    // 50,000 materials: with a linear search per name (each new one checked against all before)
    // this took about 20 s; a hash look-up takes well under a second. A generous bound for a
    // loaded machine; the 200,000-material figure is in the test's commit message.
    std::string text = kHead;
    const int n = 50000;
    for (int i = 0; i < n; ++i) text += "material m" + std::to_string(i) + " diffuse=0.5\n";
    text += "sphere center=0,0,0 radius=1 material=m" + std::to_string(n - 1) + "\n";
    auto t0 = std::chrono::steady_clock::now();
    pgt::Scene sc = pgt::parse_scene(text, "many.scene", ".");
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_EQ(sc.materials.size(), size_t(n) + 1);
    EXPECT_EQ(sc.spheres[0].material, n);
    EXPECT_EQ(sc.find_material("m123"), 124);
    EXPECT_EQ(sc.find_material("nope"), -1);
    EXPECT_LT(s, 8.0) << "parsing " << n << " materials took " << s << " s";
    // Duplicates are still found through the index.
    EXPECT_EQ(error_of(kHead + "material m diffuse=0.2\n"), "bad.scene:4: material: material 'm' defined twice");
    // A material replaced by name keeps its index; materials added directly are still found.
    sc.set_material("m7", pgloss_physical{{0.2, 0.2, 0.2}, 0.05, 0.1, 0.1, PGLOSS_NORM_WARD});
    EXPECT_EQ(sc.find_material("m7"), 8);
    EXPECT_DOUBLE_EQ(sc.materials[8].physical.rho_s, 0.05);
    pgt::Material extra;
    extra.name = "direct";
    sc.materials.push_back(extra);
    EXPECT_EQ(sc.find_material("direct"), n + 1);
    sc.set_material("after", pgloss_physical{{0.2, 0.2, 0.2}, 0.0, 0.1, 0.1, PGLOSS_NORM_WARD});
    EXPECT_EQ(sc.find_material("after"), n + 2);
    EXPECT_EQ(sc.find_material("direct"), n + 1);
}

pgt::Scene small_scene() {
    pgt::Scene sc = pgt::parse_scene(kHead + "sphere center=0,0,0 radius=1 material=m\n", "t.scene", ".");
    sc.settings.width = 16, sc.settings.height = 12;
    return sc;
}

TEST(Hardening, NonFiniteSamplesFailTheRenderInsteadOfBlackPixels) {
    // A light of radiance FLT_MAX (finite, set past the parser's checks), 10 × 10 at height 1
    // over a floor: next-event estimation's L·f·A·cos·cos_l/d² overflows float where
    // A cos cos_l / d² > π/ρd. Before, such samples were dropped and the pixels came back dark
    // with exit 0.
    pgt::Scene sc = pgt::parse_scene(
        "camera position=0,0.5,0 look_at=0,0,-1\nmaterial m diffuse=0.5\n"
        "quad corner=-5,0,5 edge1=10,0,0 edge2=0,0,-10 material=m\n"
        "light corner=-5,1,-5 edge1=10,0,0 edge2=0,0,10 radiance=1\n",
        "t.scene", ".");
    sc.lights[0].radiance = glm::vec3(FLT_MAX);
    sc.settings.width = 8, sc.settings.height = 6;
    pgt::Renderer r(sc);
    pgt::RenderOptions o;
    o.progress = false;
    o.threads = 2;
    pgt::RenderSettings s = sc.settings;
    s.spp = 2;
    try {
        r.render(s, o);
        ADD_FAILURE() << "render returned";
    } catch (const std::runtime_error &e) {
        EXPECT_NE(std::string(e.what()).find("samples were not finite (first: pixel ("), std::string::npos) << e.what();
    }
}

TEST(Hardening, RendererRefusesNonFiniteRadiance) {
    // A scene built in code skips the parser; the renderer checks what it is given.
    pgt::Scene sc = small_scene();
    sc.environment = glm::vec3(INFINITY);
    EXPECT_THROW(pgt::Renderer r(sc), pgt::SceneError);
}

TEST(Hardening, CancelKeepsEveryFinishedTile) {
    pgt::Scene sc = small_scene();
    sc.settings.width = 64, sc.settings.height = 48;
    pgt::Renderer r(sc);
    std::atomic<bool> cancel{false};
    pgt::RenderOptions o;
    o.progress = false;
    o.threads = 2;
    o.cancel = &cancel;
    // Cancelled from another thread at an arbitrary moment, mostly in the middle of a pass, as
    // a SIGINT handler would.
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(300));
        cancel = true;
    });
    pgt::RenderSettings s = sc.settings;
    s.spp = 1 << 20;
    pgt::RenderStats st;
    pgt::Image img = r.render(s, o, &st);
    canceller.join();
    EXPECT_TRUE(st.interrupted);
    EXPECT_GE(st.spp, 1);
    EXPECT_LT(st.spp, 1 << 20);
    // A grey Lambertian sphere (ρd 0.5) in a uniform environment of 1: each sample of a sphere
    // pixel is exactly 0.5 (cosine-weighted environment sampling), the background 1; pixels on
    // the silhouette mix the two. Every pixel is a mean over its own tile's samples, none 0.
    for (float v : img.rgb) {
        ASSERT_TRUE(std::isfinite(v));
        ASSERT_GE(v, 0.5f - 1e-5f);
        ASSERT_LE(v, 1.0f + 1e-5f);
    }
}

TEST(Hardening, ImagesAreWrittenWholeOrNotAtAll) {
    fs::path dir = fs::path(PGLOSS_TEST_OUT) / "atomic";
    fs::remove_all(dir);
    fs::create_directories(dir);
    pgt::Image img;
    img.width = 4, img.height = 2;
    img.rgb.assign(24, 0.25f);
    pgt::write_exr(img, (dir / "a.exr").string());
    pgt::Image back = pgt::read_image((dir / "a.exr").string());
    EXPECT_EQ(back.rgb, img.rgb);
    // A failed write leaves neither a truncated file nor a temporary behind.
    EXPECT_THROW(pgt::write_exr(img, (dir / "missing" / "b.exr").string()), std::runtime_error);
    size_t files = 0;
    for (auto &e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 1u);
    // A failed final rename says why (the removal of the temporary file used to overwrite the
    // reason: "cannot write …: Success"): here the final name is a non-empty folder.
    fs::create_directories(dir / "c.exr" / "inside");
    try {
        pgt::write_exr(img, (dir / "c.exr").string());
        ADD_FAILURE() << "write_exr onto a folder returned";
    } catch (const std::runtime_error &e) {
        const std::string what = e.what();
        EXPECT_EQ(what.find("Success"), std::string::npos) << what;
        EXPECT_EQ(what, "cannot write " + (dir / "c.exr").string() + ": " + std::strerror(EISDIR)) << what;
    }
    files = 0;
    for (auto &e : fs::directory_iterator(dir)) files += e.is_regular_file() ? 1 : 0;
    EXPECT_EQ(files, 1u);  // no temporary left behind
}

// A contact sheet's labels fit their cells: out/fig12.png cut its bottom-right label at the
// sheet's edge and the labels ran into the next cell (their width was never measured).
TEST(Hardening, ContactSheetLabelsStayInTheirCells) {
    const float bg = std::lround(0.08f * 255) / 255.0f;
    auto is_bg = [&](const pgt::Image &im, int x, int y) {
        const float *p = &im.rgb[3 * (size_t(y) * size_t(im.width) + size_t(x))];
        return std::fabs(p[0] - bg) < 0.6f / 255 && std::fabs(p[1] - bg) < 0.6f / 255 && std::fabs(p[2] - bg) < 0.6f / 255;
    };
    fs::path dir = fs::path(PGLOSS_TEST_OUT) / "sheet";
    fs::create_directories(dir);
    const int pad = 6;  // image.cpp's margin between cells
    // Fig. 12's labels (DejaVu through OIIO: ASCII), and a long one that only fits broken into lines.
    const std::vector<std::string> labels = {
        "black rho_s .099 alpha .04\nc .183  d .96", "white rho_s .099 alpha .04\nc .0578  d .96",
        "grey rho_s .0413 alpha .04\nc .0578  d .96", "a label much longer than any cell is wide, which must wrap",
        "short", "black rho_s .0125 alpha .04\nc .057  d .96"};
    for (int cw : {80, 160, 256}) {
        const int chh = cw * 3 / 4;
        std::vector<pgt::SheetCell> cells;
        for (const std::string &l : labels) {
            pgt::SheetCell c;
            c.display.width = cw, c.display.height = chh;
            c.display.rgb.assign(size_t(3 * cw * chh), 0.0f);
            for (size_t i = 2; i < c.display.rgb.size(); i += 3) c.display.rgb[i] = 1.0f;  // pure blue
            c.label = l;
            cells.push_back(c);
        }
        const std::string png = (dir / ("sheet" + std::to_string(cw) + ".png")).string();
        pgt::write_png(pgt::contact_sheet(cells, 3, "Fig. 12: same physical gloss (top), same perceptual gloss (bottom)"), png);
        pgt::Image im = pgt::read_image(png);
        const int W = im.width, H = im.height;
        ASSERT_EQ(W, pad + 3 * (cw + pad));
        // The cells' rows: where the first column's image is blue.
        std::vector<int> tops;
        for (int y = 0; y < H; ++y) {
            const float *p = &im.rgb[3 * (size_t(y) * size_t(W) + size_t(pad))];
            bool blue = p[2] > 0.99f && p[0] < 0.01f;
            const float *q = y ? p - 3 * size_t(W) : nullptr;
            if (blue && !(q && q[2] > 0.99f && q[0] < 0.01f)) tops.push_back(y);
        }
        ASSERT_EQ(tops.size(), 2u) << cw;
        for (int r = 0; r < 2; ++r) {
            const int label_top = tops[size_t(r)] + chh, label_end = r == 0 ? tops[1] - pad : H - pad;
            for (int col = 0; col < 3; ++col) {
                const int x0 = pad + col * (cw + pad);
                int text = 0;
                for (int y = tops[size_t(r)]; y < (r == 0 ? tops[1] : H); ++y) {
                    for (int x = x0 + cw; x < x0 + cw + pad; ++x)  // the gap after the cell, the sheet's edge
                        ASSERT_TRUE(is_bg(im, x, y)) << "cw " << cw << ": text in the gap at (" << x << ", " << y << ")";
                    if (y >= label_top && y < label_end) {
                        for (int x = x0; x < x0 + cw; ++x) text += !is_bg(im, x, y);
                        // Not cut at the cell's edge: the label's last columns stay empty.
                        for (int x = x0 + cw - 2; x < x0 + cw; ++x)
                            ASSERT_TRUE(is_bg(im, x, y)) << "cw " << cw << ": label cut at (" << x << ", " << y << ")";
                    }
                }
                EXPECT_GT(text, 10) << "cw " << cw << ": no label drawn under cell " << 3 * r + col;
            }
        }
        for (int y = H - pad; y < H; ++y)  // below the last labels: nothing
            for (int x = 0; x < W; ++x) ASSERT_TRUE(is_bg(im, x, y)) << "cw " << cw << ": text in the bottom margin";
    }
}

}  // namespace
