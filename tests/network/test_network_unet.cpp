// test_network_unet.cpp: the UNets on oneDNN (network/unet.h) against the
// plain double-precision reference (reference/unet_reference.h): random
// networks of odd widths (every channel count padded, every concatenation
// split off a block boundary) and the real weights of the default, small
// and large networks, at several sizes; the shape each file gives (FLOPs,
// receptive field, tile overlap, computed by hand from the table of
// docs/network.md); the refusals of a network that is not OIDN's; plan
// reuse and thread counts. The real-weight tests FAIL when the weights are
// missing: run scripts/fetch-weights.
#include "network/unet.h"
#include "reference/unet_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace {

using mcdenoise::Tensor;
using mcdenoise::TensorMap;
using mcdenoise::UNet;

std::string weights_dir()
{
    const char* dir = std::getenv("MCD_WEIGHTS_DIR");
    return dir && *dir ? dir : MCD_WEIGHTS_DIR_DEFAULT;
}

TensorMap read_weights(const std::string& file)
{
    TensorMap tensors;
    std::string error;
    EXPECT_TRUE(mcdenoise::read_tza(weights_dir() + "/" + file, tensors, error))
        << error << " (run scripts/fetch-weights, or set MCD_WEIGHTS_DIR)";
    return tensors;
}

/// A random convolution `name`, in -> out, scaled so activations neither
/// vanish nor explode through the network (He initialisation).
void add_conv(TensorMap& tensors, const std::string& name, int in, int out, std::mt19937& rng)
{
    std::normal_distribution<float> weight(0.0f, std::sqrt(2.0f / (9.0f * float(in))));
    std::uniform_real_distribution<float> bias(-0.05f, 0.1f);
    Tensor w { name + ".weight", { out, in, 3, 3 }, "oihw", {} };
    Tensor b { name + ".bias", { out }, "x", {} };
    for (int i = 0; i < out * in * 9; ++i)
        w.values.push_back(weight(rng));
    for (int i = 0; i < out; ++i)
        b.values.push_back(bias(rng));
    tensors[w.name] = w;
    tensors[b.name] = b;
}

/// A default-shaped UNet with odd widths and `c` input channels.
TensorMap random_default_unet(int c, unsigned seed)
{
    std::mt19937 rng(seed);
    TensorMap t;
    add_conv(t, "enc_conv0", c, 7, rng);
    add_conv(t, "enc_conv1", 7, 9, rng);
    add_conv(t, "enc_conv2", 9, 11, rng);
    add_conv(t, "enc_conv3", 11, 13, rng);
    add_conv(t, "enc_conv4", 13, 17, rng);
    add_conv(t, "enc_conv5a", 17, 19, rng);
    add_conv(t, "enc_conv5b", 19, 20, rng);
    add_conv(t, "dec_conv4a", 20 + 13, 21, rng);
    add_conv(t, "dec_conv4b", 21, 22, rng);
    add_conv(t, "dec_conv3a", 22 + 11, 23, rng);
    add_conv(t, "dec_conv3b", 23, 24, rng);
    add_conv(t, "dec_conv2a", 24 + 9, 25, rng);
    add_conv(t, "dec_conv2b", 25, 26, rng);
    add_conv(t, "dec_conv1a", 26 + c, 27, rng);
    add_conv(t, "dec_conv1b", 27, 28, rng);
    add_conv(t, "dec_conv0", 28, 3, rng);
    return t;
}

/// A large-shaped UNet (two convolutions a level, dec_conv1c last) with
/// odd widths, one of them over a block of 16.
TensorMap random_large_unet(int c, unsigned seed)
{
    std::mt19937 rng(seed);
    TensorMap t;
    const int enc[5] = { 5, 18, 7, 9, 33 };
    int in           = c;
    for (int level = 0; level < 5; ++level) {
        add_conv(t, "enc_conv" + std::to_string(level + 1) + "a", in, enc[level], rng);
        add_conv(t, "enc_conv" + std::to_string(level + 1) + "b", enc[level], enc[level], rng);
        in = enc[level];
    }
    const int dec[4] = { 6, 20, 10, 12 };
    int up           = enc[4];
    for (int level = 3; level >= 0; --level) {
        const int skip = level == 0 ? c : enc[level - 1];
        add_conv(t, "dec_conv" + std::to_string(level + 1) + "a", up + skip, dec[level], rng);
        add_conv(t, "dec_conv" + std::to_string(level + 1) + "b", dec[level], dec[level], rng);
        up = dec[level];
    }
    add_conv(t, "dec_conv1c", dec[0], 3, rng);
    return t;
}

/// Random planar input in [0, 1), as the network sees its inputs.
unetref::Activations random_input(int channels, int height, int width, unsigned seed)
{
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> value(0.0, 1.0);
    unetref::Activations x { channels, height, width, {} };
    for (size_t i = 0; i < size_t(channels) * height * width; ++i)
        x.values.push_back(double(float(value(rng))));
    return x;
}

std::vector<float> run_engine(UNet& net, const unetref::Activations& input, int nthreads = 0)
{
    std::vector<float> in(input.values.begin(), input.values.end());
    std::vector<float> out(size_t(3) * input.height * input.width);
    std::string error;
    EXPECT_TRUE(net.run(in.data(), input.height, input.width, out.data(), nthreads, error)) << error;
    return out;
}

/// Mean of |a - b| / (|b| + 0.01) (the measure), and the largest
/// |a - b| over the largest |b|.
struct Agreement {
    double mean_relative = 0, max_over_peak = 0;
};

Agreement agreement(const std::vector<float>& ours, const unetref::Activations& reference)
{
    double sum = 0, worst = 0, peak = 0;
    for (size_t i = 0; i < ours.size(); ++i) {
        const double diff = std::abs(double(ours[i]) - reference.values[i]);
        sum += diff / (std::abs(reference.values[i]) + 0.01);
        worst = std::max(worst, diff);
        peak  = std::max(peak, std::abs(reference.values[i]));
    }
    return { sum / double(ours.size()), worst / std::max(peak, 1e-30) };
}

void expect_matches_reference(const TensorMap& tensors, int channels, int height, int width,
                              unsigned seed)
{
    UNet net;
    std::string error;
    ASSERT_TRUE(net.load(std::make_shared<const TensorMap>(tensors), "test", error)) << error;
    const auto input     = random_input(channels, height, width, seed);
    const auto reference = unetref::unet(tensors, input);
    const Agreement a    = agreement(run_engine(net, input), reference);
    EXPECT_LE(a.mean_relative, 1e-5) << width << "x" << height;
    EXPECT_LE(a.max_over_peak, 1e-5) << width << "x" << height;
    double peak = 0;
    for (double v : reference.values)
        peak = std::max(peak, v);
    EXPECT_GT(peak, 1e-3) << "the output vanished: the check would be empty";
}

TEST(NetworkUNet, RandomDefaultNetworksMatchTheReference)
{
    for (int c : { 3, 6, 9 })
        expect_matches_reference(random_default_unet(c, 10 + unsigned(c)), c, 32, 48, 1);
    expect_matches_reference(random_default_unet(9, 5), 9, 16, 16, 2);
    expect_matches_reference(random_default_unet(3, 6), 3, 48, 16, 3);
}

TEST(NetworkUNet, RandomLargeNetworksMatchTheReference)
{
    expect_matches_reference(random_large_unet(9, 7), 9, 32, 48, 4);
    expect_matches_reference(random_large_unet(3, 8), 3, 16, 64, 5);
}

TEST(NetworkUNet, RealWeightsMatchTheReference)
{
    const struct {
        const char* file;
        int channels;
    } files[] = { { "rt_hdr_alb_nrm.tza", 9 }, { "rt_hdr_calb_cnrm_small.tza", 9 },
                  { "rt_hdr_calb_cnrm_large.tza", 9 }, { "rt_alb_large.tza", 3 },
                  { "rt_nrm.tza", 3 } };
    for (const auto& f : files) {
        SCOPED_TRACE(f.file);
        expect_matches_reference(read_weights(f.file), f.channels, 32, 48, 9);
    }
}

TEST(NetworkUNet, ShapesOfTheRealFiles)
{
    // By hand from docs/network.md's table: sum of 2 x 9 x in x out / 4^level.
    const struct {
        const char* file;
        int channels;
        double flops;
        int field, overlap;
    } files[] = { { "rt_hdr_calb_cnrm.tza", 9, 250812, 174, 96 },
                  { "rt_hdr_calb_cnrm_large.tza", 9, 624384, 202, 112 },
                  { "rt_alb_large.tza", 3, 610560, 202, 112 },
                  { "rt_hdr.tza", 3, 250812 - 18 * 6 * 32 - 18 * 6 * 64, 174, 96 } };
    for (const auto& f : files) {
        SCOPED_TRACE(f.file);
        UNet net;
        std::string error;
        ASSERT_TRUE(net.load(weights_dir() + "/" + f.file, error)) << error;
        EXPECT_EQ(net.layout().input_channels, f.channels);
        EXPECT_EQ(net.layout().receptive_field(), f.field);
        EXPECT_EQ(net.layout().tile_overlap(), f.overlap);
        EXPECT_DOUBLE_EQ(net.layout().flops_per_pixel(), f.flops);
    }
}

TEST(NetworkUNet, RefusesNetworksThatAreNotOidns)
{
    const auto expect_refused = [](TensorMap t, const std::string& words) {
        mcdenoise::UNetLayout layout;
        std::string error;
        EXPECT_FALSE(mcdenoise::read_unet_layout(t, "bad.tza", layout, error));
        EXPECT_NE(error.find("bad.tza"), std::string::npos) << error;
        EXPECT_NE(error.find(words), std::string::npos) << error;
    };
    auto no_bias = random_default_unet(3, 1);
    no_bias.erase("dec_conv3b.bias");
    expect_refused(no_bias, "dec_conv3b");
    auto stranger = random_default_unet(3, 1);
    stranger["attention.weight"] = stranger["enc_conv0.weight"];
    expect_refused(stranger, "attention.weight");
    auto broken_chain = random_default_unet(3, 1);
    std::mt19937 rng(1);
    add_conv(broken_chain, "enc_conv2", 8, 11, rng);
    expect_refused(broken_chain, "enc_conv2");
    auto no_level = random_default_unet(3, 1);
    for (const char* n : { "enc_conv4.weight", "enc_conv4.bias" })
        no_level.erase(n);
    expect_refused(no_level, "level 3");
    auto wide_output = random_default_unet(3, 1);
    add_conv(wide_output, "dec_conv0", 28, 4, rng);
    expect_refused(wide_output, "not 3");
}

TEST(NetworkUNet, RefusesSidesThatAreNotMultiplesOf16)
{
    UNet net;
    std::string error;
    std::vector<float> in(9 * 24 * 32), out(3 * 24 * 32);
    EXPECT_FALSE(net.run(in.data(), 24, 32, out.data(), 0, error));
    EXPECT_NE(error.find("no network"), std::string::npos) << error;
    ASSERT_TRUE(net.load(std::make_shared<const TensorMap>(random_default_unet(9, 1)), "test", error))
        << error;
    EXPECT_FALSE(net.run(in.data(), 24, 32, out.data(), 0, error));
    EXPECT_NE(error.find("multiples of 16"), std::string::npos) << error;
}

TEST(NetworkUNet, PlansAreReusedAndRemadeExactly)
{
    UNet net;
    std::string error;
    ASSERT_TRUE(net.load(std::make_shared<const TensorMap>(random_default_unet(6, 3)), "test", error))
        << error;
    const auto a = random_input(6, 32, 32, 1), b = random_input(6, 48, 64, 2);
    const auto first = run_engine(net, a);
    run_engine(net, b);
    EXPECT_EQ(run_engine(net, a), first);
    EXPECT_EQ(run_engine(net, a), first);
}

TEST(NetworkUNet, ThreadCountsAgree)
{
    UNet net;
    std::string error;
    ASSERT_TRUE(net.load(std::make_shared<const TensorMap>(random_default_unet(9, 4)), "test", error))
        << error;
    const auto input = random_input(9, 64, 80, 3);
    const auto one = run_engine(net, input, 1), two = run_engine(net, input, 2);
    for (size_t i = 0; i < one.size(); ++i)
        ASSERT_NEAR(one[i], two[i], 1e-5f * (1.0f + std::abs(one[i]))) << i;
}

TEST(NetworkUNet, WorkingMemoryGrowsWithThePixels)
{
    UNet net;
    std::string error;
    ASSERT_TRUE(net.load(weights_dir() + "/rt_hdr_calb_cnrm_large.tza", error)) << error;
    const size_t small = net.working_bytes(256, 256, error), large = net.working_bytes(512, 512, error);
    ASSERT_GT(small, 0u) << error;
    // Activations: at least the full-resolution concatenation and two
    // scratch buffers (112 + 2 x 64 channels of float).
    EXPECT_GE(small, size_t(256) * 256 * 240 * 4);
    EXPECT_GT(large, 3 * small);
    EXPECT_LT(large, 5 * small);
}

}  // namespace
