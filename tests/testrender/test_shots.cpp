// test_shots.cpp: testrender's animation. Frame 0 is the still render every
// existing file was made with; each frame has its own noise while the static
// shot converges to the same picture at every frame; and the motion AOV is
// checked independently of how it is computed: the surface point a pixel
// sees, carried by its motion vector to the neighbour frame, is the point
// that frame's own camera ray sees there (so a flipped sign fails), and the
// neighbour frame's rendered id buffer agrees at the warped positions.
#include "camera.h"
#include "integrator.h"
#include "render.h"
#include "rng.h"
#include "scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>
#include <string>

namespace {

using namespace testrender;

const char* const still_scenes[] = { "cornell", "mirrors", "textured", "dof", "interior" };

Scene scene_at(const std::string& name, int frame)
{
    Scene s;
    EXPECT_TRUE(make_scene(name, s, frame)) << name;
    return s;
}

RenderBuffers render_frame(const std::string& name, int frame, int w, int h, int spp,
                           uint64_t seed)
{
    RenderSettings settings;
    settings.width = w;
    settings.height = h;
    settings.spp = spp;
    settings.seed = seed;
    settings.frame = frame;
    return render(scene_at(name, frame), settings);
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/// FNV-1a over the bytes of the floats.
uint64_t fnv1a(const std::vector<float>& v)
{
    uint64_t h = 1469598103934665603ULL;
    for (float f : v) {
        uint32_t u;
        std::memcpy(&u, &f, sizeof u);
        for (int k = 0; k < 4; ++k) {
            h ^= (u >> (8 * k)) & 0xffu;
            h *= 1099511628211ULL;
        }
    }
    return h;
}

TEST(TestRenderShots, FrameZeroIsTheStillRender)
{
    // Hashes of the beauty at 16x12, 2 spp, seed 1, as rendered before
    // testrender had frames: the cached reference set and every earlier
    // file stay valid.
    EXPECT_EQ(fnv1a(render_frame("cornell", 0, 16, 12, 2, 1).beauty), 0x43d4c49d154d0f7dULL);
    EXPECT_EQ(fnv1a(render_frame("dof", 0, 16, 12, 2, 1).beauty), 0xe46b89cfa518a855ULL);
    for (const char* name : still_scenes) {
        // the default (no frame) is frame 0
        Scene plain;
        ASSERT_TRUE(make_scene(name, plain));
        RenderSettings settings;
        settings.width = 12;
        settings.height = 10;
        settings.spp = 2;
        const RenderBuffers a = render(plain, settings);
        const RenderBuffers b = render_frame(name, 0, 12, 10, 2, 1);
        EXPECT_TRUE(same_bits(a.beauty, b.beauty)) << name;
        EXPECT_TRUE(same_bits(a.albedo, b.albedo)) << name;
        // the stills do not move: no motion at any frame
        const RenderBuffers later = render_frame(name, 7, 12, 10, 2, 1);
        for (float m : later.motion)
            EXPECT_EQ(m, 0.0f) << name;
        EXPECT_TRUE(same_bits(a.id, later.id)) << name;
        EXPECT_FALSE(same_bits(a.beauty, later.beauty)) << name;
    }
}

TEST(TestRenderShots, EveryFrameHasItsOwnSeed)
{
    std::set<uint64_t> seeds;
    const int frames = 1000;
    for (uint64_t seed : { 1, 1000 })
        for (int f = 0; f < frames; ++f)
            seeds.insert(frame_seed(seed, f));
    EXPECT_EQ(seeds.size(), size_t(2 * frames));
    EXPECT_EQ(frame_seed(1, 0), 1u);
}

/// Per-pixel z-scores of the difference of two renders of the same picture
/// with independent noise, from their `var` channels: the fraction within
/// 3 sigma and the mean (both images converge to the same mean: ~0).
void expect_same_picture(const RenderBuffers& a, const RenderBuffers& b, const char* what)
{
    double sum = 0;
    int within = 0, n = 0;
    for (size_t i = 0; i < a.beauty.size(); ++i) {
        const double sigma = std::sqrt(double(a.variance[i]) + double(b.variance[i]));
        if (sigma == 0) {
            EXPECT_EQ(a.beauty[i], b.beauty[i]) << what << " " << i;
            continue;
        }
        const double z = (double(a.beauty[i]) - double(b.beauty[i])) / sigma;
        sum += z;
        within += std::abs(z) < 3;
        ++n;
    }
    ASSERT_GT(n, 0) << what;
    EXPECT_GT(double(within) / n, 0.95) << what;
    // the mean of n unit z-scores has standard deviation 1/sqrt(n)
    EXPECT_LT(std::abs(sum / n), 5 / std::sqrt(double(n))) << what;
}

TEST(TestRenderShots, StaticShotNoiseChangesButThePictureDoesNot)
{
    const int w = 16, h = 12, spp = 16;
    const RenderBuffers f0 = render_frame("shot_static", 0, w, h, spp, 1);
    const RenderBuffers f1 = render_frame("shot_static", 1, w, h, spp, 1);
    const RenderBuffers f9 = render_frame("shot_static", 9, w, h, spp, 1);
    EXPECT_FALSE(same_bits(f0.beauty, f1.beauty));
    EXPECT_FALSE(same_bits(f1.beauty, f9.beauty));
    EXPECT_TRUE(same_bits(f0.id, f9.id));
    EXPECT_TRUE(same_bits(f0.depth, f9.depth));
    for (float m : f9.motion)
        EXPECT_EQ(m, 0.0f);
    expect_same_picture(f0, f1, "frames 0, 1");
    expect_same_picture(f1, f9, "frames 1, 9");
    // high-spp references of two frames (seed 1000) agree with each other
    const int ref_spp = 256;
    expect_same_picture(render_frame("shot_static", 0, w, h, ref_spp, 1000),
                        render_frame("shot_static", 5, w, h, ref_spp, 1000), "references 0, 5");
}

/// Motion components with their signs flipped (1 keeps, -1 flips).
struct Signs {
    double x = 1, y = 1, z = 1, w = 1;
};

/// For every pixel of `name` at `frame` whose center ray hits something:
/// carry its film position by the motion vector to the previous and next
/// frame and cast that frame's own center ray there. Counts the rays that
/// hit the same object and the ones among them that hit the same
/// object-space point (within `tolerance` world units).
struct WarpCheck {
    int moving = 0;        ///< pixel halves whose motion exceeds `min_motion`
    int same_object = 0;   ///< ... whose warped ray hits the same object
    int same_point = 0;    ///< ... at the same object-space point
};

constexpr double point_tolerance = 1e-4;  ///< world units; a pixel spans ~0.03 here
constexpr double min_motion = 0.5;        ///< pixels: a flipped sign then moves >= 1 pixel

WarpCheck warp_to_neighbours(const std::string& name, int frame, int w, int h, Signs signs,
                             int component = -1)
{
    const Scene scene = scene_at(name, frame);
    const Scene neighbour[2] = { scene_at(name, frame - 1), scene_at(name, frame + 1) };
    const RenderBuffers b = render_frame(name, frame, w, h, 1, 1);
    const Camera camera(scene.camera, w, h);
    WarpCheck c;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const double fx = x + 0.5, fy = y + 0.5;
            Hit hit;
            if (!scene.intersect(camera.center_ray(fx, fy), hit))
                continue;
            const Vec3 local = hit.position - scene.objects[size_t(hit.object)].shape.anchor();
            const float* m = &b.motion[(size_t(y) * size_t(w) + size_t(x)) * 4];
            // previous: (fx + X, fy - Y); next: (fx - Z, fy + W)
            const double to[2][2] = { { fx + signs.x * m[0], fy - signs.y * m[1] },
                                      { fx - signs.z * m[2], fy + signs.w * m[3] } };
            for (int k = 0; k < 2; ++k) {
                const double mx = m[2 * k], my = m[2 * k + 1];
                const double size = component < 0 ? std::hypot(mx, my)
                                                  : std::abs(double(m[component]));
                if (size < min_motion || (component >= 0 && component / 2 != k))
                    continue;
                ++c.moving;
                const Scene& other = neighbour[k];
                Hit seen;
                const Camera other_camera(other.camera, w, h);
                if (!other.intersect(other_camera.center_ray(to[k][0], to[k][1]), seen)
                    || seen.object != hit.object)
                    continue;
                ++c.same_object;
                const Vec3 other_local
                    = seen.position - other.objects[size_t(seen.object)].shape.anchor();
                c.same_point += length(other_local - local) < point_tolerance;
            }
        }
    return c;
}

class MovingShot : public ::testing::TestWithParam<const char*> {};

constexpr int warp_w = 64, warp_h = 48;
constexpr int warp_frame = 5;  ///< moving both sideways and vertically in both shots

TEST_P(MovingShot, MotionCarriesEachPixelToItsSurfacePoint)
{
    const WarpCheck c = warp_to_neighbours(GetParam(), warp_frame, warp_w, warp_h, {});
    std::printf("%s: %d moving, %d same object, %d same point\n", GetParam(), c.moving,
                c.same_object, c.same_point);
    EXPECT_GT(c.moving, warp_w * warp_h / 40);
    // the rest are disoccluded in the neighbour frame (hidden behind another object)
    EXPECT_GT(c.same_object, 0.9 * c.moving);
    // a point turning out of view at a silhouette may land on the same
    // object elsewhere; everything else must be exact
    EXPECT_GT(c.same_point, 0.98 * c.same_object);
}

TEST_P(MovingShot, FlippingAnySignBreaksTheWarp)
{
    const char* names = "XYZW";
    for (int component = 0; component < 4; ++component) {
        Signs signs;
        double* flip[4] = { &signs.x, &signs.y, &signs.z, &signs.w };
        *flip[component] = -1;
        const WarpCheck right = warp_to_neighbours(GetParam(), warp_frame, warp_w, warp_h, {},
                                                   component);
        const WarpCheck wrong = warp_to_neighbours(GetParam(), warp_frame, warp_w, warp_h, signs,
                                                   component);
        SCOPED_TRACE(std::string("component ") + names[component]);
        ASSERT_GT(right.moving, 20);
        EXPECT_GT(right.same_point, 0.85 * right.moving);
        EXPECT_LT(wrong.same_point, 0.05 * wrong.moving);
    }
}

TEST_P(MovingShot, NeighbourIdBufferAgreesAtTheWarpedPosition)
{
    const std::string name = GetParam();
    const int w = warp_w, h = warp_h;
    const RenderBuffers cur = render_frame(name, warp_frame, w, h, 1, 1);
    const RenderBuffers prev = render_frame(name, warp_frame - 1, w, h, 1, 1);
    const RenderBuffers next = render_frame(name, warp_frame + 1, w, h, 1, 1);
    auto id_at = [&](const RenderBuffers& b, double fx, double fy) {
        const int x = int(std::floor(fx)), y = int(std::floor(fy));
        if (x < 0 || y < 0 || x >= w || y >= h)
            return -2.0f;
        return b.id[size_t(y) * size_t(w) + size_t(x)];
    };
    int interior = 0, agree = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const float id = cur.id[size_t(y) * size_t(w) + size_t(x)];
            bool inside = id >= 0;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx)
                    inside = inside && cur.id[size_t(y + dy) * size_t(w) + size_t(x + dx)] == id;
            const float* m = &cur.motion[(size_t(y) * size_t(w) + size_t(x)) * 4];
            if (!inside || std::hypot(m[0], m[1]) < 2 * min_motion)
                continue;
            ++interior;
            const double fx = x + 0.5, fy = y + 0.5;
            agree += id_at(prev, fx + m[0], fy - m[1]) == id && id_at(next, fx - m[2], fy + m[3]) == id;
        }
    std::printf("%s: %d interior moving pixels, %d agree\n", name.c_str(), interior, agree);
    ASSERT_GT(interior, 20);
    EXPECT_GT(agree, 0.95 * interior);
}

TEST(TestRenderShots, BackgroundMotionIsTheCameraRotationOnly)
{
    // shot_truck only translates the camera: a direction at infinity stays put
    const RenderBuffers b = render_frame("shot_truck", warp_frame, 32, 24, 1, 1);
    int misses = 0;
    for (size_t p = 0; p < b.id.size(); ++p)
        if (b.id[p] < 0) {
            ++misses;
            for (int k = 0; k < 4; ++k)
                EXPECT_NEAR(b.motion[p * 4 + size_t(k)], 0.0f, 1e-4f) << p;
        }
    EXPECT_GT(misses, 0);
    // a camera panning right by one pixel's angle per frame: the sky moves left
    Scene pan;
    pan.camera.eye = { 0, 0, 0 };
    pan.camera.look_at = { 0, 0, -1 };
    pan.camera.vfov_degrees = 40;
    const int size = 41;
    const double pixel_angle = std::atan(2 * std::tan(20 * pi / 180) / size);  // at the center
    NeighbourFrame before, after;
    before.camera = after.camera = pan.camera;
    before.camera.look_at = { -std::sin(pixel_angle), 0, -std::cos(pixel_angle) };
    after.camera.look_at = { std::sin(pixel_angle), 0, -std::cos(pixel_angle) };
    pan.neighbours = { before, after };
    RenderSettings settings;
    settings.width = settings.height = size;
    settings.spp = 1;
    const RenderBuffers p = render(pan, settings);
    const float* m = &p.motion[(size_t(size / 2) * size + size / 2) * 4];
    // the center was one pixel right in the previous frame (camera looked
    // further left) and is one pixel left in the next: X = +1, Z = +1
    EXPECT_NEAR(m[0], 1.0f, 1e-3f);
    EXPECT_NEAR(m[1], 0.0f, 1e-6f);
    EXPECT_NEAR(m[2], 1.0f, 1e-3f);
    EXPECT_NEAR(m[3], 0.0f, 1e-6f);
}

INSTANTIATE_TEST_SUITE_P(Shots, MovingShot, ::testing::Values("shot_object", "shot_truck"));

}  // namespace
