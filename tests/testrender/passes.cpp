// passes.cpp: turning a pixel's summed sample passes into the Cycles-style
// light passes: colours averaged, light divided by its colour.
#include "passes.h"

namespace testrender {

const std::vector<std::string>& pass_channel_names()
{
    static const std::vector<std::string> names = [] {
        std::vector<std::string> n;
        for (const char* pass : { "DiffDir", "DiffInd", "DiffCol", "GlossDir", "GlossInd",
                                  "GlossCol", "TransDir", "TransInd", "TransCol", "Emit", "Env" })
            for (const char* c : { ".R", ".G", ".B" })
                n.push_back(std::string(pass) + c);
        return n;
    }();
    return names;
}

void finish_passes(const SamplePasses& sums, int spp, float* out)
{
    const double inv = 1.0 / spp;
    Vec3 emit = sums.emit * inv;
    for (int lobe = 0; lobe < lobe_count; ++lobe) {
        const Vec3 colour = sums.colour[lobe] * inv;
        const Vec3 light[2] = { sums.direct[lobe] * inv, sums.indirect[lobe] * inv };
        float* dir = out + 9 * lobe;
        float* ind = dir + 3;
        float* col = dir + 6;
        for (int c = 0; c < 3; ++c) {
            col[c] = float(colour[c]);
            if (colour[c] > 0) {
                dir[c] = float(light[0][c] / colour[c]);
                ind[c] = float(light[1][c] / colour[c]);
            } else {
                dir[c] = ind[c] = 0;
                const double lost = light[0][c] + light[1][c];
                emit = emit + Vec3(c == 0 ? lost : 0, c == 1 ? lost : 0, c == 2 ? lost : 0);
            }
        }
    }
    const Vec3 env = sums.env * inv;
    for (int c = 0; c < 3; ++c) {
        out[27 + c] = float(emit[c]);
        out[30 + c] = float(env[c]);
    }
}

}  // namespace testrender
