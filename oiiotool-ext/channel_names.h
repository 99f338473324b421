// channel_names.h: an image's channel names taken apart
// ("<layer>.<pass>.<component>"), listed for messages, and the spec of a
// subset of its channels. The layer below channel discovery (channels.h)
// and the Cryptomatte id search (cryptomatte.h).
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <string>
#include <vector>

namespace mcdtool {

using OIIO::ImageSpec;

/// A channel name taken apart: "<layer>.<pass>.<component>".
struct ChannelName {
    std::string layer;
    std::string pass;
    std::string component;
};

/// Splits a channel name. "R" -> ("", "", "R"); "Z" -> ("", "Z", "Z");
/// "N.X" -> ("", "N", "X"); "ViewLayer.Denoising Normal.X" ->
/// ("ViewLayer", "Denoising Normal", "X").
ChannelName split_name(const std::string& name);

/// The spec of channels `indices` of an image of spec `from`, as float:
/// its windows and metadata, those channels' names, alpha and depth.
ImageSpec extracted_spec(const ImageSpec& from, const std::vector<int>& indices);

/// "N.X,N.Y,N.Z": the names of `indices`.
std::string channel_names(const ImageSpec& spec, const std::vector<int>& indices);

/// "R,G,B,...": every channel of `spec`, for error messages.
std::string all_channel_names(const ImageSpec& spec);

}  // namespace mcdtool
