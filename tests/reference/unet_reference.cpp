// unet_reference.cpp: OIDN's UNets in plain double loops (unet_reference.h).
#include "reference/unet_reference.h"

#include <algorithm>
#include <string>

namespace unetref {

namespace {

Activations zeros(int channels, int height, int width)
{
    return { channels, height, width, std::vector<double>(size_t(channels) * height * width, 0.0) };
}

}  // namespace

Activations conv_relu(const mcdenoise::TensorMap& weights, const char* name, const Activations& x)
{
    const auto& w   = weights.at(std::string(name) + ".weight");
    const auto& b   = weights.at(std::string(name) + ".bias");
    const int out_c = w.dims[0], in_c = w.dims[1];
    Activations y   = zeros(out_c, x.height, x.width);
    for (int o = 0; o < out_c; ++o)
        for (int yy = 0; yy < x.height; ++yy)
            for (int xx = 0; xx < x.width; ++xx) {
                double sum = b.values[size_t(o)];
                for (int i = 0; i < in_c; ++i)
                    for (int ky = 0; ky < 3; ++ky)
                        for (int kx = 0; kx < 3; ++kx) {
                            const int sy = yy + ky - 1, sx = xx + kx - 1;
                            if (sy < 0 || sy >= x.height || sx < 0 || sx >= x.width)
                                continue;
                            sum += double(w.values[((size_t(o) * in_c + i) * 3 + ky) * 3 + kx])
                                   * x.at(i, sy, sx);
                        }
                y.at(o, yy, xx) = std::max(sum, 0.0);
            }
    return y;
}

Activations pool(const Activations& x)
{
    Activations y = zeros(x.channels, x.height / 2, x.width / 2);
    for (int c = 0; c < y.channels; ++c)
        for (int yy = 0; yy < y.height; ++yy)
            for (int xx = 0; xx < y.width; ++xx)
                y.at(c, yy, xx) = std::max({ x.at(c, 2 * yy, 2 * xx), x.at(c, 2 * yy, 2 * xx + 1),
                                             x.at(c, 2 * yy + 1, 2 * xx), x.at(c, 2 * yy + 1, 2 * xx + 1) });
    return y;
}

Activations upsample(const Activations& x)
{
    Activations y = zeros(x.channels, x.height * 2, x.width * 2);
    for (int c = 0; c < y.channels; ++c)
        for (int yy = 0; yy < y.height; ++yy)
            for (int xx = 0; xx < y.width; ++xx)
                y.at(c, yy, xx) = x.at(c, yy / 2, xx / 2);
    return y;
}

Activations concat(const Activations& a, const Activations& b)
{
    Activations y = zeros(a.channels + b.channels, a.height, a.width);
    std::copy(a.values.begin(), a.values.end(), y.values.begin());
    std::copy(b.values.begin(), b.values.end(), y.values.begin() + long(a.values.size()));
    return y;
}

namespace {

/// training/model.py's UNet (default and small widths alike).
Activations default_unet(const mcdenoise::TensorMap& w, const Activations& input)
{
    Activations x = conv_relu(w, "enc_conv0", input);
    x             = pool(conv_relu(w, "enc_conv1", x));
    const Activations pool1 = x;
    x             = pool(conv_relu(w, "enc_conv2", x));
    const Activations pool2 = x;
    x             = pool(conv_relu(w, "enc_conv3", x));
    const Activations pool3 = x;
    x             = pool(conv_relu(w, "enc_conv4", x));
    x             = conv_relu(w, "enc_conv5b", conv_relu(w, "enc_conv5a", x));
    x = conv_relu(w, "dec_conv4b", conv_relu(w, "dec_conv4a", concat(upsample(x), pool3)));
    x = conv_relu(w, "dec_conv3b", conv_relu(w, "dec_conv3a", concat(upsample(x), pool2)));
    x = conv_relu(w, "dec_conv2b", conv_relu(w, "dec_conv2a", concat(upsample(x), pool1)));
    x = conv_relu(w, "dec_conv1b", conv_relu(w, "dec_conv1a", concat(upsample(x), input)));
    return conv_relu(w, "dec_conv0", x);
}

/// training/model.py's UNetLarge.
Activations large_unet(const mcdenoise::TensorMap& w, const Activations& input)
{
    Activations x = pool(conv_relu(w, "enc_conv1b", conv_relu(w, "enc_conv1a", input)));
    const Activations pool1 = x;
    x = pool(conv_relu(w, "enc_conv2b", conv_relu(w, "enc_conv2a", x)));
    const Activations pool2 = x;
    x = pool(conv_relu(w, "enc_conv3b", conv_relu(w, "enc_conv3a", x)));
    const Activations pool3 = x;
    x = pool(conv_relu(w, "enc_conv4b", conv_relu(w, "enc_conv4a", x)));
    x = conv_relu(w, "enc_conv5b", conv_relu(w, "enc_conv5a", x));
    x = conv_relu(w, "dec_conv4b", conv_relu(w, "dec_conv4a", concat(upsample(x), pool3)));
    x = conv_relu(w, "dec_conv3b", conv_relu(w, "dec_conv3a", concat(upsample(x), pool2)));
    x = conv_relu(w, "dec_conv2b", conv_relu(w, "dec_conv2a", concat(upsample(x), pool1)));
    x = conv_relu(w, "dec_conv1b", conv_relu(w, "dec_conv1a", concat(upsample(x), input)));
    return conv_relu(w, "dec_conv1c", x);
}

}  // namespace

Activations unet(const mcdenoise::TensorMap& weights, const Activations& input)
{
    return weights.count("enc_conv1a.weight") ? large_unet(weights, input) : default_unet(weights, input);
}

}  // namespace unetref
