// test_testrender.cpp: the renderer's ground truth is right where it can be
// computed by hand (depth, normal and id of known pixels, the reflection id
// at the center of a mirror sphere), its output does not depend on the
// thread count, and the file has the documented channels and metadata.
// Convergence (noise falling as 1/spp) is checked on the reference set in
// test_refset.cpp.
#include "camera.h"
#include "output.h"
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

Scene scene_named(const std::string& name)
{
    Scene s;
    EXPECT_TRUE(make_scene(name, s)) << name;
    return s;
}

RenderBuffers render_scene(const std::string& name, int w, int h, int spp, uint64_t seed,
                           int threads = 0)
{
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.spp = spp;
    settings.seed = seed;
    settings.threads = threads;
    return render(scene_named(name), settings);
}

size_t at(const RenderBuffers& b, int x, int y) { return size_t(y) * size_t(b.width) + size_t(x); }

Vec3 normal_at(const RenderBuffers& b, int x, int y)
{
    const size_t p = at(b, x, y) * 3;
    return { b.normal[p], b.normal[p + 1], b.normal[p + 2] };
}

// Cornell camera (scenes.cpp): eye (0, 1, 3.9) looking along -z, vertical
// field of view 40 degrees; the room is [-1,1] x [0,2] x [-1,1], open at +z.
constexpr double cornell_eye_z = 3.9;
constexpr double cornell_half_fov_tan = 0.36397023426620234;  // tan(20 degrees)

TEST(TestRenderAovs, CornellBackWallFloorAndMissByHand)
{
    const int size = 65;  // odd: the center pixel's center ray is the view axis
    const RenderBuffers b = render_scene("cornell", size, size, 2, 1);

    // center pixel: straight down the axis onto the back wall at z = -1
    EXPECT_FLOAT_EQ(b.depth[at(b, 32, 32)], float(cornell_eye_z + 1.0));
    EXPECT_EQ(b.id[at(b, 32, 32)], 3.0f);  // back wall
    EXPECT_EQ(b.reflid[at(b, 32, 32)], -1.0f);
    const Vec3 n = normal_at(b, 32, 32);
    EXPECT_NEAR(n.x, 0, 1e-6);
    EXPECT_NEAR(n.y, 0, 1e-6);
    EXPECT_NEAR(n.z, 1, 1e-6);

    // center column, row 60: the view ray (0, sy, -1) meets the floor y = 0
    // at parameter 1 / -sy, z = 3.9 - 1 / -sy = 0.71 (inside the room, between
    // the two spheres)
    const double sy = (1 - 2 * 60.5 / size) * cornell_half_fov_tan;
    const double floor_distance = (1 / -sy) * std::sqrt(1 + sy * sy);
    EXPECT_NEAR(b.depth[at(b, 32, 60)], floor_distance, 1e-5);
    EXPECT_EQ(b.id[at(b, 32, 60)], 1.0f);  // floor
    const Vec3 nf = normal_at(b, 32, 60);
    EXPECT_NEAR(nf.y, 1, 1e-6);

    // the top-left corner looks past the box's open front: a miss
    EXPECT_TRUE(std::isinf(b.depth[at(b, 0, 0)]) && b.depth[at(b, 0, 0)] > 0);
    EXPECT_EQ(b.id[at(b, 0, 0)], -1.0f);
    EXPECT_EQ(b.reflid[at(b, 0, 0)], -1.0f);
    EXPECT_EQ(b.beauty[at(b, 0, 0) * 3], 0.0f);  // black background
    const Vec3 nm = normal_at(b, 0, 0);
    EXPECT_EQ(nm.x * nm.x + nm.y * nm.y + nm.z * nm.z, 0.0);
}

TEST(TestRenderAovs, MirrorSphereCenterReflectsTheWallBehindTheCamera)
{
    // mirrors scene: mirror sphere id 10 centered at (0, 0.5, -0.6); the
    // camera is inside a closed room whose front wall (behind it) is id 6.
    // At the sphere's visible center the normal points back at the camera, so
    // the reflection ray passes the camera and hits that wall.
    const Scene scene = scene_named("mirrors");
    const int w = 96, h = 72;
    const Camera camera(scene.camera, w, h);
    double fx, fy;
    ASSERT_TRUE(camera.project({ 0, 0.5, -0.6 }, fx, fy));
    const int px = int(fx), py = int(fy);
    const RenderBuffers b = render_scene("mirrors", w, h, 1, 1);
    EXPECT_EQ(b.id[at(b, px, py)], 10.0f);
    EXPECT_EQ(b.reflid[at(b, px, py)], 6.0f);

    // reflid is set only where the first hit is a mirror (ids 10..13), and
    // every mirror pixel reflects something in this closed room
    int mirror_pixels = 0;
    for (size_t i = 0; i < b.id.size(); ++i) {
        const bool mirror = b.id[i] >= 10 && b.id[i] <= 13;
        mirror_pixels += mirror;
        if (mirror)
            EXPECT_GE(b.reflid[i], 1.0f) << "pixel " << i;
        else
            EXPECT_EQ(b.reflid[i], -1.0f) << "pixel " << i;
    }
    EXPECT_GT(mirror_pixels, w * h / 20);
}

TEST(TestRenderAovs, HalfBuffersAverageToTheBeauty)
{
    const RenderBuffers b = render_scene("interior", 32, 24, 8, 3);
    for (size_t i = 0; i < b.beauty.size(); ++i) {
        const double half_mean = 0.5 * (double(b.half_a[i]) + double(b.half_b[i]));
        EXPECT_NEAR(b.beauty[i], half_mean, 1e-5 * (1 + std::abs(half_mean))) << i;
        EXPECT_GE(b.variance[i], 0.0f);
        EXPECT_TRUE(std::isfinite(b.variance[i]));
    }
}

/// Form factor from a point to a parallel a x b rectangle at height 1 whose
/// corner is straight above the point (Howell's catalogue, configuration
/// B-3 with the plane distance scaled to 1).
double corner_form_factor(double a, double b)
{
    const double ra = std::sqrt(1 + a * a), rb = std::sqrt(1 + b * b);
    return (a / ra * std::atan(b / ra) + b / rb * std::atan(a / rb)) / (2 * testrender::pi);
}

/// A plane (id 1) with material `m` under a 1 x 1 light of radiance 1 at
/// height 1 (id 2), nothing else; the camera's center pixel sees a tiny
/// patch around the origin from (0, 0.5, 2).
Scene plane_under_light(const Material& m)
{
    Scene s;
    s.name = "plane";
    const int floor = s.add_material(m);
    const int light = s.add_material(Material::emitter(Vec3(1.0)));
    s.add(Shape::quad({ -10, 0, 10 }, { 20, 0, 0 }, { 0, 0, -20 }), floor, 1);
    s.add(Shape::quad({ -0.5, 1, -0.5 }, { 1, 0, 0 }, { 0, 0, 1 }), light, 2);  // faces -y
    s.camera.eye = { 0, 0.5, 2 };
    s.camera.look_at = { 0, 0, 0 };
    s.camera.vfov_degrees = 0.5;
    return s;
}

/// Render the center pixel of `scene` and check it against `expected`
/// within 4 standard deviations of the pixel mean (from the var channel).
void expect_center_radiance(const Scene& scene, double expected)
{
    RenderSettings settings;
    settings.width = settings.height = 3;
    settings.spp = 20000;
    const RenderBuffers b = render(scene, settings);
    ASSERT_EQ(b.id[at(b, 1, 1)], 1.0f);
    for (int c = 0; c < 3; ++c) {
        const size_t i = at(b, 1, 1) * 3 + size_t(c);
        const double sigma = std::sqrt(double(b.variance[i]));
        EXPECT_GT(sigma, 0.0);
        EXPECT_NEAR(b.beauty[i], expected, 4 * sigma + 1e-4)
            << "channel " << c << ": expected " << expected << ", sigma " << sigma;
    }
}

TEST(TestRenderRadiance, DiffusePlaneMatchesTheFormFactor)
{
    // radiance = albedo / pi * E, E = pi * L * 4 * F(0.5, 0.5): light reaches
    // the plane both by light sampling and by BSDF sampling (MIS), so this
    // checks the estimator is unbiased, not only consistent.
    const double albedo = 0.5;
    const Scene s = plane_under_light(Material::diffuse(Texture::constant(Vec3(albedo))));
    expect_center_radiance(s, albedo / testrender::pi
                                  * (testrender::pi * 4 * corner_form_factor(0.5, 0.5)));
}

TEST(TestRenderRadiance, GlossyPlaneMatchesQuadratureOverTheLight)
{
    // radiance = integral over the light of f(wo, wi) cos(wi) L cos_l / d^2
    // dA, by the midpoint rule with bsdf_eval: checks that the glossy lobe's
    // sampling density, the light sampling and their MIS weights agree with
    // its evaluation.
    const Material m = Material::glossy(Texture::constant(Vec3(0.2)), Vec3(0.5), 0.3);
    const Scene s = plane_under_light(m);
    const Vec3 x0(0, 0, 0), n(0, 1, 0);
    const Frame frame(n);
    const Vec3 wo = frame.to_local(normalize(s.camera.eye - x0));
    const int steps = 600;
    const double da = 1.0 / (double(steps) * steps);
    double sum = 0;
    for (int i = 0; i < steps; ++i)
        for (int j = 0; j < steps; ++j) {
            const Vec3 y(-0.5 + (i + 0.5) / steps, 1, -0.5 + (j + 0.5) / steps);
            const Vec3 to = y - x0;
            const double d2 = dot(to, to);
            const Vec3 wi = to / std::sqrt(d2);
            const Vec3 f_cos = bsdf_eval(m, Vec3(0.2), wo, frame.to_local(wi));
            sum += f_cos.x * wi.y / d2 * da;
        }
    expect_center_radiance(s, sum);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(TestRenderDeterminism, IdenticalForOneTwoAndSevenThreads)
{
    for (const char* name : { "cornell", "dof" }) {
        const RenderBuffers one = render_scene(name, 40, 33, 4, 7, 1);
        for (int threads : { 2, 7 }) {
            const RenderBuffers many = render_scene(name, 40, 33, 4, 7, threads);
            EXPECT_TRUE(same_bits(one.beauty, many.beauty)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.albedo, many.albedo)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.normal, many.normal)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.depth, many.depth)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.id, many.id)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.reflid, many.reflid)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.variance, many.variance)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.half_a, many.half_a)) << name << " " << threads;
            EXPECT_TRUE(same_bits(one.half_b, many.half_b)) << name << " " << threads;
        }
    }
    // a different seed gives a different image
    EXPECT_FALSE(same_bits(render_scene("cornell", 40, 33, 4, 7).beauty,
                           render_scene("cornell", 40, 33, 4, 8).beauty));
}

TEST(TestRenderOutput, ChannelsAndMetadata)
{
    RenderSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.spp = 2;
    settings.seed = 5;
    const RenderBuffers b = render(scene_named("cornell"), settings);
    const std::string path = ::testing::TempDir() + "testrender_output_test.exr";
    std::string error;
    ASSERT_TRUE(write_image(to_image(b, "cornell", settings), path, error)) << error;
    OIIO::ImageBuf in(path);
    ASSERT_TRUE(in.read(0, 0, true, OIIO::TypeDesc::FLOAT)) << in.geterror();
    const OIIO::ImageSpec& spec = in.spec();
    EXPECT_EQ(spec.format, OIIO::TypeDesc::FLOAT);
    EXPECT_EQ(spec.nchannels, 25);
    for (const std::string& name : channel_names(b))
        EXPECT_GE(spec.channelindex(name), 0) << name;
    EXPECT_EQ(spec.get_string_attribute("testrender:scene"), "cornell");
    EXPECT_EQ(spec.get_int_attribute("testrender:spp"), 2);
    EXPECT_EQ(spec.get_int_attribute("testrender:seed"), 5);
    EXPECT_EQ(spec.get_int_attribute("testrender:frame", -1), 0);
    EXPECT_GE(spec.get_float_attribute("testrender:render_seconds", -1), 0.0f);
    EXPECT_GT(spec.get_float_attribute("testrender:samples_per_second", -1), 0.0f);
    // the file holds exactly the buffers
    const int id_channel = spec.channelindex("id");
    const int r_channel = spec.channelindex("R");
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            EXPECT_EQ(in.getchannel(x, y, 0, id_channel), b.id[at(b, x, y)]);
            EXPECT_EQ(in.getchannel(x, y, 0, r_channel), b.beauty[at(b, x, y) * 3]);
        }
    std::remove(path.c_str());
}

}  // namespace
