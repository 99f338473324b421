// A minimal outside program: filters a constant image through the installed
// library and exits 0 only if the result is right.
#include <mcdenoise/mcdenoise.h>
#include <OpenImageIO/imagebufalgo.h>
#include <cstdio>

int main()
{
    OIIO::ImageBuf src(OIIO::ImageSpec(8, 8, 3, OIIO::TypeDesc::FLOAT));
    const float value[3] = { 0.25f, 0.5f, 1.0f };
    OIIO::ImageBufAlgo::fill(src, value);
    OIIO::ImageBuf out = mcdenoise::median(src, 3);
    float pixel[3];
    out.getpixel(4, 4, pixel);
    if (out.has_error() || pixel[0] != 0.25f || pixel[2] != 1.0f) {
        std::fprintf(stderr, "consumer: unexpected result %s\n", out.geterror().c_str());
        return 1;
    }
    return 0;
}
