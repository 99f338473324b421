// test_errors.cpp: bad sizes, ROIs and images are reported through the
// destination's error, with a false return, and leave the destination as it was.
#include <mcdenoise/mcdenoise.h>

#include "support/test_images.h"

#include <gtest/gtest.h>

namespace {

using OIIO::ImageBuf;
using OIIO::ROI;

using BoolForm = bool (*)(ImageBuf&, const ImageBuf&, int, ROI, int);

struct Named {
    const char* name;
    BoolForm run;
};

const Named ops[] = { { "mean", static_cast<BoolForm>(mcdenoise::mean) },
                      { "median", static_cast<BoolForm>(mcdenoise::median) },
                      { "gaussian", static_cast<BoolForm>(mcdenoise::gaussian) } };

void expect_rejected(const Named& op, const ImageBuf& src, int size, ROI roi,
                     const std::string& words)
{
    ImageBuf untouched_dst = testimg::random_image(8, 8, 3, 99);
    const std::vector<float> before = testimg::pixels(untouched_dst);
    EXPECT_FALSE(op.run(untouched_dst, src, size, roi, 0)) << op.name;
    const std::string message = untouched_dst.geterror();
    EXPECT_NE(message.find(op.name), std::string::npos) << message;
    EXPECT_NE(message.find(words), std::string::npos) << message;
    EXPECT_EQ(testimg::pixels(untouched_dst), before) << op.name << " changed dst";

    ImageBuf empty_dst;
    EXPECT_FALSE(op.run(empty_dst, src, size, roi, 0));
    EXPECT_FALSE(empty_dst.initialized()) << op.name << " allocated dst on error";
}

TEST(Errors, EvenSize)
{
    const ImageBuf src = testimg::random_image(16, 16, 3, 1);
    for (const Named& op : ops)
        expect_rejected(op, src, 4, {}, "odd");
}

TEST(Errors, SizeOutOfRange)
{
    const ImageBuf src = testimg::random_image(16, 16, 3, 1);
    for (const Named& op : ops)
        for (int size : { 0, -3, 257, 1 << 30 })
            expect_rejected(op, src, size, {}, "between 1 and 255");
}

TEST(Errors, RoiOutsideTheImage)
{
    const ImageBuf src = testimg::random_image(16, 16, 3, 1);
    for (const Named& op : ops) {
        expect_rejected(op, src, 3, ROI(10, 20, 0, 16), "outside");
        expect_rejected(op, src, 3, ROI(-1, 4, 0, 4), "outside");
        expect_rejected(op, src, 3, ROI(0, 16, 0, 16, 0, 1, 5, 6), "channels");
    }
}

TEST(Errors, EmptyBeauty)
{
    const ImageBuf nothing;
    for (const Named& op : ops)
        expect_rejected(op, nothing, 3, {}, "empty");
}

TEST(Errors, ValueFormCarriesTheError)
{
    const ImageBuf src = testimg::random_image(16, 16, 3, 1);
    const ImageBuf out = mcdenoise::median(src, 6);
    EXPECT_TRUE(out.has_error());
    EXPECT_NE(out.geterror().find("median: size must be odd, got 6"), std::string::npos);
}

}  // namespace
