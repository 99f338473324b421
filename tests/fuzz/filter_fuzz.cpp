// filter_fuzz.cpp: libFuzzer target for every library filter (the rows of
// tests/support/filter_table.h) on arbitrary sizes, data windows, ROIs,
// channel counts and pixel types, with NaN, infinities, denormals and huge
// values in the beauty and the guides, guides with other (covering or not)
// data windows and wrong channel counts. Invariants: the call succeeds or
// fails the same way on 1 thread and on N; a failure leaves `dst` empty and
// says why; a success is bit-identical on 1 and N threads and on a split
// of the ROI, and holds finite values only (but for the per-pixel rows,
// which copy non-finite values by contract).
#include "fuzz_dir.h"
#include "support/filter_table.h"

#include <OpenImageIO/imagebuf.h>

#include <fuzzer/FuzzedDataProvider.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace {

using OIIO::ImageBuf;
using OIIO::ImageSpec;
using OIIO::ROI;
using OIIO::TypeDesc;
using testfilters::GuideBit;
using testfilters::GuideSet;

/// Largest image side tried: windows up to 255 still clip on every side.
constexpr int max_side = 40;
/// Farthest data window origin from 0.
constexpr int max_origin = 50;
/// Most channels tried in the beauty.
constexpr int max_channels = 8;
/// Most threads tried.
constexpr int max_threads = 16;

/// Values that break naive arithmetic.
const float hostile_values[] = { std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::infinity(),
                                 -std::numeric_limits<float>::infinity(),
                                 std::numeric_limits<float>::denorm_min(),
                                 -1e-40f,
                                 std::numeric_limits<float>::max(),
                                 -std::numeric_limits<float>::max(),
                                 1e30f,
                                 0.0f,
                                 -0.0f };
constexpr int n_hostile = int(sizeof(hostile_values) / sizeof(hostile_values[0]));
/// Kind bytes below this pick a small whole number (ids, labels).
constexpr int small_integer_kinds = 128;

/// One value: a hostile one, a small whole number, or arbitrary float bits.
float next_value(FuzzedDataProvider& in)
{
    const int kind = in.ConsumeIntegral<uint8_t>();
    if (kind < n_hostile)
        return hostile_values[kind];
    if (kind < small_integer_kinds)
        return float(kind % 8) - 1.0f;
    const uint32_t bits = in.ConsumeIntegral<uint32_t>();
    float value;
    std::memcpy(&value, &bits, sizeof value);
    return value;
}

/// A pixel type an input may be stored in.
TypeDesc next_format(FuzzedDataProvider& in)
{
    static const TypeDesc formats[] = { TypeDesc::FLOAT, TypeDesc::HALF, TypeDesc::UINT8,
                                        TypeDesc::UINT16, TypeDesc::UINT32, TypeDesc::DOUBLE };
    return formats[in.ConsumeIntegralInRange<size_t>(0, sizeof(formats) / sizeof(formats[0]) - 1)];
}

/// An image over `window` with `nchannels` channels filled from the input.
ImageBuf next_image(FuzzedDataProvider& in, const ROI& window, int nchannels)
{
    ImageSpec spec(window.width(), window.height(), nchannels, next_format(in));
    spec.x = window.xbegin;
    spec.y = window.ybegin;
    ImageBuf image(spec);
    std::vector<float> values(size_t(window.npixels()) * size_t(nchannels));
    for (float& v : values)
        v = next_value(in);
    image.set_pixels(image.roi(), TypeDesc::FLOAT, values.data());
    return image;
}

/// A guide for `beauty`: usually covering it with a margin, sometimes
/// short of it on one side; usually with the right channel count.
ImageBuf next_guide(FuzzedDataProvider& in, const ROI& beauty, GuideBit role)
{
    ROI window = beauty;
    window.xbegin -= in.ConsumeIntegralInRange(-1, 5);
    window.ybegin -= in.ConsumeIntegralInRange(-1, 5);
    window.xend += in.ConsumeIntegralInRange(-1, 5);
    window.yend += in.ConsumeIntegralInRange(-1, 5);
    if (window.width() < 1 || window.height() < 1)
        window = beauty;
    int nchannels = testfilters::guide_channels(role);
    if (in.ConsumeIntegralInRange(0, 15) == 0)
        nchannels = in.ConsumeIntegralInRange(1, 4);
    return next_image(in, window, nchannels);
}

/// The ROI to filter: usually the default, else any box near the window.
ROI next_roi(FuzzedDataProvider& in, const ROI& window, int nchannels)
{
    if (in.ConsumeBool())
        return {};
    const int xb = in.ConsumeIntegralInRange(window.xbegin - 2, window.xend);
    const int yb = in.ConsumeIntegralInRange(window.ybegin - 2, window.yend);
    const int xe = in.ConsumeIntegralInRange(xb, window.xend + 2);
    const int ye = in.ConsumeIntegralInRange(yb, window.yend + 2);
    const int cb = in.ConsumeIntegralInRange(0, nchannels);
    const int ce = in.ConsumeIntegralInRange(cb, nchannels + 1);
    return ROI(xb, xe, yb, ye, 0, 1, cb, ce);
}

/// The float values of `image` over `roi`.
std::vector<float> values_of(const ImageBuf& image, const ROI& roi)
{
    std::vector<float> values(size_t(roi.npixels()) * size_t(roi.nchannels()));
    image.get_pixels(roi, TypeDesc::FLOAT, values.data());
    return values;
}

/// True if both hold the same bits (NaN payloads included).
bool same_bits(const std::vector<float>& a, const std::vector<float>& b)
{
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    FuzzedDataProvider in(data, size);
    const auto& table = testfilters::filter_table();
    const testfilters::FilterRow& row = table[in.ConsumeIntegralInRange<size_t>(0, table.size() - 1)];
    const int width = in.ConsumeIntegralInRange(1, max_side);
    const int height = in.ConsumeIntegralInRange(1, max_side);
    const int x0 = in.ConsumeIntegralInRange(-max_origin, max_origin);
    const int y0 = in.ConsumeIntegralInRange(-max_origin, max_origin);
    const int nchannels = in.ConsumeIntegralInRange(1, max_channels);
    const int window_size = in.ConsumeIntegralInRange(-2, 259);
    const int nthreads = in.ConsumeIntegralInRange(2, max_threads);
    const ROI window(x0, x0 + width, y0, y0 + height, 0, 1, 0, nchannels);
    const ROI roi = next_roi(in, window, nchannels);

    GuideSet guides;
    ImageBuf* slots[] = { &guides.object_id, &guides.reflect_id, &guides.normal,
                          &guides.depth,     &guides.albedo,     &guides.variance };
    for (int bit = 0; bit < 6; ++bit)
        if (row.guides & (1u << bit))
            *slots[bit] = next_guide(in, window, GuideBit(1u << bit));
    const ImageBuf beauty = next_image(in, window, nchannels);

    ImageBuf one, many;
    const bool ok_one = row.run(one, beauty, guides, window_size, roi, 1);
    const bool ok_many = row.run(many, beauty, guides, window_size, roi, nthreads);
    mcdfuzz::require(ok_one == ok_many, "success depends on the thread count");
    if (!ok_one) {
        mcdfuzz::require(!one.initialized(), "a failed call allocated dst");
        mcdfuzz::require(!one.geterror().empty(), "a failed call gave no message");
        return 0;
    }
    const ROI done = one.roi();
    const std::vector<float> result = values_of(one, done);
    mcdfuzz::require(same_bits(result, values_of(many, done)), "1 and N threads differ");
    for (size_t i = 0; i < result.size() && !row.per_pixel; ++i)
        mcdfuzz::require(std::isfinite(result[i]), std::string(row.name) + ": value " + std::to_string(i)
                                                       + " of the result is " + std::to_string(result[i])
                                                       + ", not finite");
    if (done.height() >= 2) {
        ROI top = done;
        top.yend = in.ConsumeIntegralInRange(done.ybegin + 1, done.yend - 1);
        if (roi.defined())
            top.chbegin = roi.chbegin;
        ImageBuf piece;
        mcdfuzz::require(row.run(piece, beauty, guides, window_size, top, 1), "a split of a good ROI failed");
        mcdfuzz::require(same_bits(values_of(piece, top), values_of(one, top)), "a split of the ROI differs");
    }
    return 0;
}
