// cryptomatte.h: object ids from Cryptomatte layers, the id pass most
// production renderers write (Arnold, RenderMan, Cycles, V-Ray): finding a
// layer's rank-0 id channel and turning its float-coded 32-bit hashes into
// whole-number ids the library compares exactly.
#pragma once

#include <OpenImageIO/imagebuf.h>

#include <string>

namespace mcdtool {

/// True if channel `c` of `spec` holds Cryptomatte ids: `<name>NN.R` or
/// `<name>NN.B` (the id of each rank pair) of a layer named by the file's
/// `cryptomatte/<key>/name` metadata, or of Cycles' `CryptoObject` or
/// Arnold's `crypto_object` when the metadata was stripped.
bool is_cryptomatte_id_channel(const OIIO::ImageSpec& spec, int c);

/// The rank-0 id channel (`<name>00.R`, the object covering most of each
/// pixel) of a Cryptomatte object layer (one whose name ends in "object",
/// in any case) in view layer `layer` of `spec`, or -1 if there is none.
int find_cryptomatte_object_ids(const OIIO::ImageSpec& spec, const std::string& layer);

/// Channel `c` of `src` as a one-channel UINT32 image of its values' bits:
/// each Cryptomatte hash becomes the whole number it was coded from (0, no
/// object, stays 0), with `src`'s windows and metadata.
OIIO::ImageBuf cryptomatte_ids(const OIIO::ImageBuf& src, int c);

}  // namespace mcdtool
