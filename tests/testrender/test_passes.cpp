// test_passes.cpp: the light passes add up to the beauty in every pixel of
// every scene, each light lands in the pass it belongs to (emitters, sky,
// mirrors, glass, direct against indirect), the colours are the materials'
// lobe weights, turning the passes on changes no other channel, and the
// transparent film gives premultiplied colour with alpha.
#include "output.h"
#include "passes.h"
#include "render.h"
#include "scene.h"

#include <OpenImageIO/imagebuf.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

namespace {

using namespace testrender;

/// Offsets of each pass in a pixel's pass channels (see pass_channel_names).
enum PassOffset {
    diff_dir = 0, diff_ind = 3, diff_col = 6, gloss_dir = 9, gloss_ind = 12, gloss_col = 15,
    trans_dir = 18, trans_ind = 21, trans_col = 24, emit = 27, env = 30
};

RenderBuffers render_passes(const Scene& scene, int w, int h, int spp, bool passes = true)
{
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.spp = spp;
    settings.passes = passes;
    return render(scene, settings);
}

Scene scene_named(const std::string& name)
{
    Scene s;
    EXPECT_TRUE(make_scene(name, s)) << name;
    return s;
}

/// Pass `offset`, channel c, of pixel p.
float pass(const RenderBuffers& b, size_t p, int offset, int c)
{
    return b.passes[p * pass_channels + size_t(offset) + size_t(c)];
}

/// DiffCol (DiffDir + DiffInd) + GlossCol (...) + TransCol (...) + Emit + Env.
double pass_sum(const RenderBuffers& b, size_t p, int c)
{
    double sum = double(pass(b, p, emit, c)) + pass(b, p, env, c);
    for (int lobe = 0; lobe < lobe_count; ++lobe) {
        const int o = 9 * lobe;
        sum += double(pass(b, p, o + 6, c)) * (double(pass(b, p, o, c)) + pass(b, p, o + 3, c));
    }
    return sum;
}

/// Relative tolerance of the sum: a few float roundings of positive terms.
constexpr double sum_tolerance = 1e-5;

class EveryScene : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScene, PassesAddUpToTheBeauty)
{
    const RenderBuffers b = render_passes(scene_named(GetParam()), 24, 18, 4);
    ASSERT_EQ(b.passes.size(), b.id.size() * pass_channels);
    for (size_t p = 0; p < b.id.size(); ++p)
        for (int c = 0; c < 3; ++c) {
            const double beauty = b.beauty[p * 3 + size_t(c)];
            EXPECT_NEAR(pass_sum(b, p, c), beauty, sum_tolerance * std::abs(beauty))
                << "pixel " << p << " channel " << c;
            for (int o = 0; o < pass_channels; o += 3)
                EXPECT_TRUE(std::isfinite(pass(b, p, o, c)) && pass(b, p, o, c) >= 0)
                    << "pixel " << p << " pass " << pass_channel_names()[size_t(o)];
        }
}

TEST_P(EveryScene, PassesChangeNoOtherChannel)
{
    const Scene scene = scene_named(GetParam());
    const RenderBuffers with = render_passes(scene, 12, 9, 2, true);
    const RenderBuffers without = render_passes(scene, 12, 9, 2, false);
    EXPECT_TRUE(without.passes.empty());
    EXPECT_EQ(std::memcmp(with.beauty.data(), without.beauty.data(), with.beauty.size() * 4), 0);
    EXPECT_EQ(std::memcmp(with.variance.data(), without.variance.data(), with.variance.size() * 4),
              0);
    EXPECT_EQ(std::memcmp(with.albedo.data(), without.albedo.data(), with.albedo.size() * 4), 0);
}

std::vector<std::string> all_scenes() { return scene_names(); }

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene, ::testing::ValuesIn(all_scenes()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                             return info.param;
                         });

/// A diffuse plane (id 1) under a one-sided square light (id 2), nothing
/// else: the center pixel sees the plane, whose light is all direct.
Scene lit_plane(const Material& m)
{
    Scene s;
    s.name = "plane";
    const int floor = s.add_material(m);
    const int light = s.add_material(Material::emitter(Vec3(1.0)));
    s.add(Shape::quad({ -10, 0, 10 }, { 20, 0, 0 }, { 0, 0, -20 }), floor, 1);
    s.add(Shape::quad({ -0.5, 1, -0.5 }, { 1, 0, 0 }, { 0, 0, 1 }), light, 2);
    s.camera.eye = { 0, 0.5, 2 };
    s.camera.look_at = { 0, 0, 0 };
    s.camera.vfov_degrees = 0.5;
    return s;
}

TEST(TestRenderPasses, DiffusePlaneIsDiffuseDirectOnly)
{
    const Vec3 albedo(0.5, 0.25, 0.125);
    const RenderBuffers b = render_passes(lit_plane(Material::diffuse(Texture::constant(albedo))),
                                          3, 3, 64);
    const size_t p = 4;  // center
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(pass(b, p, diff_col, c), float(albedo[c]));
        EXPECT_GT(pass(b, p, diff_dir, c), 0.0f);
        // the same irradiance for every colour: the colour is divided out
        EXPECT_FLOAT_EQ(pass(b, p, diff_dir, c), pass(b, p, diff_dir, 0));
        for (int o : { diff_ind, gloss_dir, gloss_ind, gloss_col, trans_dir, trans_ind,
                       trans_col, emit, env })
            EXPECT_EQ(pass(b, p, o, c), 0.0f) << pass_channel_names()[size_t(o)];
    }
}

TEST(TestRenderPasses, GlossyPlaneSplitsItsDirectLightBetweenTheLobes)
{
    const Vec3 base(0.2, 0.3, 0.4), f0(0.5, 0.5, 0.5);
    const RenderBuffers b = render_passes(
        lit_plane(Material::glossy(Texture::constant(base), f0, 0.3)), 3, 3, 256);
    const size_t p = 4;
    for (int c = 0; c < 3; ++c) {
        EXPECT_FLOAT_EQ(pass(b, p, diff_col, c), float(base[c]));
        EXPECT_FLOAT_EQ(pass(b, p, gloss_col, c), float(f0[c]));
        EXPECT_GT(pass(b, p, diff_dir, c), 0.0f);
        EXPECT_GT(pass(b, p, gloss_dir, c), 0.0f);
        EXPECT_EQ(pass(b, p, diff_ind, c), 0.0f);
        EXPECT_EQ(pass(b, p, gloss_ind, c), 0.0f);
    }
}

/// Form factor from a point to a parallel a x b rectangle at height 1 whose
/// corner is straight above the point (as in test_testrender.cpp).
double corner_form_factor(double a, double b)
{
    const double ra = std::sqrt(1 + a * a), rb = std::sqrt(1 + b * b);
    return (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb)) / (2 * pi);
}

TEST(TestRenderPasses, GlossyPlanesDiffuseShareIsUnbiased)
{
    // the diffuse lobe alone reflects base / pi * E with E = pi * 4 F(0.5,
    // 0.5) from the unit light: the split between the lobes (by their share
    // of the BSDF, for light and BSDF samples) must not bias either pass
    const Vec3 base(0.2, 0.3, 0.4);
    const RenderBuffers b = render_passes(
        lit_plane(Material::glossy(Texture::constant(base), Vec3(0.5), 0.3)), 3, 3, 20000);
    const size_t p = 4;
    const double irradiance_over_pi = 4 * corner_form_factor(0.5, 0.5);
    for (int c = 0; c < 3; ++c) {
        // the beauty's standard error bounds the diffuse part's (a part of it)
        const double sigma = std::sqrt(double(b.variance[p * 3 + size_t(c)]));
        std::printf("channel %d: DiffCol * DiffDir %.5f, expected %.5f, sigma %.5f\n", c,
                    double(pass(b, p, diff_col, c)) * pass(b, p, diff_dir, c),
                    base[c] * irradiance_over_pi, sigma);
        EXPECT_NEAR(double(pass(b, p, diff_col, c)) * pass(b, p, diff_dir, c),
                    base[c] * irradiance_over_pi, 4 * sigma + 1e-4)
            << "channel " << c;
    }
}

/// The first pixel (row by row) whose 3x3 neighbourhood is all `id`.
size_t interior_pixel(const RenderBuffers& b, float id)
{
    for (int y = 1; y + 1 < b.height; ++y)
        for (int x = 1; x + 1 < b.width; ++x) {
            bool inside = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inside = inside && b.id[size_t(y + dy) * size_t(b.width) + size_t(x + dx)] == id;
            if (inside)
                return size_t(y) * size_t(b.width) + size_t(x);
        }
    ADD_FAILURE() << "no interior pixel of id " << id;
    return 0;
}

TEST(TestRenderPasses, EachLightLandsInItsPass)
{
    // cornell: the light (id 6) is Emit; the mirror sphere (8) is glossy
    // with its tint as colour; the walls are diffuse with their albedo
    const RenderBuffers c = render_passes(scene_named("cornell"), 64, 64, 8);
    const size_t light = interior_pixel(c, 6), mirror = interior_pixel(c, 8),
                 wall = interior_pixel(c, 3);
    const float emission[3] = { 17, 12, 4 };
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_EQ(pass(c, light, emit, ch), emission[ch]);
        EXPECT_EQ(pass(c, light, diff_col, ch), 0.0f);
        EXPECT_FLOAT_EQ(pass(c, mirror, gloss_col, ch), 0.95f);
        EXPECT_EQ(pass(c, mirror, diff_col, ch), 0.0f);
        EXPECT_GT(pass(c, mirror, gloss_ind, ch), 0.0f);  // lit walls seen in the mirror
        EXPECT_FLOAT_EQ(pass(c, wall, diff_col, ch), 0.73f);
        EXPECT_GT(pass(c, wall, diff_dir, ch), 0.0f);
        EXPECT_GT(pass(c, wall, diff_ind, ch), 0.0f);
        EXPECT_EQ(pass(c, wall, emit, ch), 0.0f);
    }
    // textured: the sky is Env; the glass sphere (7) is transmission (and
    // glossy for its reflection), colour 1
    const RenderBuffers t = render_passes(scene_named("textured"), 64, 64, 8);
    const size_t sky = interior_pixel(t, -1), glass = interior_pixel(t, 7);
    const float background[3] = { 0.35f, 0.45f, 0.6f };
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_FLOAT_EQ(pass(t, sky, env, ch), background[ch]);
        EXPECT_FLOAT_EQ(pass(t, glass, trans_col, ch), 1.0f);
        EXPECT_FLOAT_EQ(pass(t, glass, gloss_col, ch), 1.0f);
        EXPECT_GT(pass(t, glass, trans_ind, ch), 0.0f);
        EXPECT_EQ(pass(t, glass, diff_col, ch), 0.0f);
    }
}

TEST(TestRenderPasses, UncolouredLightGoesToEmit)
{
    // light in a class whose colour channel is 0 cannot be divided by it: it
    // is filed in Emit, so the sum still holds
    SamplePasses sums;
    sums.colour[glossy_lobe] = Vec3(0.0, 0.5, 0.5);
    sums.direct[glossy_lobe] = Vec3(0.25, 0.5, 0.5);
    sums.indirect[glossy_lobe] = Vec3(0.125, 0.25, 0.0);
    sums.emit = Vec3(1.0, 0.0, 0.0);
    float out[pass_channels];
    finish_passes(sums, 2, out);
    EXPECT_EQ(out[gloss_dir + 0], 0.0f);
    EXPECT_EQ(out[gloss_ind + 0], 0.0f);
    EXPECT_EQ(out[emit + 0], float((1.0 + 0.25 + 0.125) / 2));
    EXPECT_EQ(out[gloss_dir + 1], 1.0f);  // (0.5 / 2) / (0.5 / 2)
    EXPECT_EQ(out[emit + 1], 0.0f);
}

TEST(TestRenderPasses, TransparentFilmIsPremultipliedWithAlpha)
{
    const RenderBuffers b = render_passes(scene_named("transparent"), 48, 36, 8);
    ASSERT_EQ(b.alpha.size(), b.id.size());
    int clear = 0, partial = 0;
    for (size_t p = 0; p < b.id.size(); ++p) {
        const float a = b.alpha[p];
        EXPECT_TRUE(a >= 0 && a <= 1) << p;
        for (int c = 0; c < 3; ++c)
            EXPECT_LE(b.beauty[p * 3 + size_t(c)], a + 1e-6f) << "pixel " << p;
        if (a == 0) {
            ++clear;
            for (int c = 0; c < 3; ++c) {
                EXPECT_EQ(b.beauty[p * 3 + size_t(c)], 0.0f) << p;
                EXPECT_EQ(pass(b, p, env, c), 0.0f) << p;
            }
        }
        partial += a > 0 && a < 1;
    }
    EXPECT_GT(clear, int(b.id.size()) / 4);
    EXPECT_GT(partial, 0);  // antialiased silhouettes
    // opaque scenes have no alpha channel
    EXPECT_TRUE(render_passes(scene_named("cornell"), 4, 3, 1).alpha.empty());
}

TEST(TestRenderPasses, IdenticalForAnyThreadCount)
{
    for (const char* name : { "transparent", "shot_object" }) {
        Scene scene = scene_named(name);
        RenderSettings settings;
        settings.width = 20;
        settings.height = 15;
        settings.spp = 3;
        settings.passes = true;
        settings.threads = 1;
        const RenderBuffers one = render(scene, settings);
        settings.threads = 3;
        const RenderBuffers three = render(scene, settings);
        EXPECT_EQ(one.passes, three.passes) << name;
        EXPECT_EQ(one.alpha, three.alpha) << name;
        EXPECT_EQ(one.motion, three.motion) << name;
    }
}

TEST(TestRenderPasses, FileHasThePassAndAlphaChannels)
{
    RenderSettings settings;
    settings.width = 6;
    settings.height = 4;
    settings.spp = 2;
    settings.passes = true;
    const RenderBuffers b = render(scene_named("transparent"), settings);
    const std::string path = ::testing::TempDir() + "testrender_passes_test.exr";
    std::string error;
    ASSERT_TRUE(write_image(to_image(b, "transparent", settings), path, error)) << error;
    OIIO::ImageBuf in(path);
    ASSERT_TRUE(in.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << in.geterror();
    const OIIO::ImageSpec& spec = in.spec();
    EXPECT_EQ(spec.nchannels, 25 + 1 + pass_channels);
    for (const char* name : { "A", "DiffDir.R", "DiffInd.G", "DiffCol.B", "GlossDir.R",
                              "GlossInd.R", "GlossCol.R", "TransDir.R", "TransInd.R",
                              "TransCol.R", "Emit.R", "Env.B" })
        EXPECT_GE(spec.channelindex(name), 0) << name;
    EXPECT_EQ(spec.alpha_channel, spec.channelindex("A"));
    const int a = spec.channelindex("A"), col = spec.channelindex("DiffCol.G");
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            const size_t p = size_t(y) * 6 + size_t(x);
            EXPECT_EQ(in.getchannel(x, y, 0, a), b.alpha[p]);
            EXPECT_EQ(in.getchannel(x, y, 0, col), pass(b, p, diff_col, 1));
        }
    std::remove(path.c_str());
}

}  // namespace
