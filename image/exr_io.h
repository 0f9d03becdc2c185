// OpenEXR files of float32 images with named layers and string metadata: the format of every
// measured image (docs/architecture.md, "Conventions", Images).
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "image/image.h"

namespace gib::image {

// String attributes of the file header, e.g. {"gibench/scene_hash", "3f…"}. Keys have the form
// "<namespace>/<name>": the namespace is non-empty and has no ':'. That keeps them apart from the
// names OpenEXR and OpenImageIO give a meaning to (capDate, comments, oiio:*, …), so they are
// stored verbatim as EXR string attributes and read back exactly. Values are non-empty and
// contain no NUL (OpenImageIO drops empty string attributes when reading).
using Metadata = std::map<std::string, std::string>;

// A named group of channels. By channel count the main layer (name "") is stored as Y; Y, A;
// R, G, B; or R, G, B, A; layer "variance" as variance.R, variance.G, variance.B, and so on.
struct Layer {
  std::string name;
  Image image;
};

struct ExrFile {
  std::vector<Layer> layers;
  Metadata metadata;

  // nullptr when the file has no such layer.
  const Image* findLayer(std::string_view name) const;
  // The main layer; throws gib::InputError when the file has none.
  const Image& rgb() const;
};

// Writes all layers into one scanline EXR: float32 channels, ZIP compression, the metadata as
// string attributes and no time stamp, so that equal inputs give byte-identical files. Layers
// must share width and height, have 1, 3 or 4 channels and distinct names; metadata must follow
// the rules above (std::invalid_argument otherwise: a bug in the caller). The file is written
// beside `path` under a temporary name and renamed, so a failure leaves no partial file; a
// missing or unwritable directory throws gib::InputError.
void writeExr(const std::filesystem::path& path, const std::vector<Layer>& layers,
              const Metadata& metadata);

// Reads the first part of any EXR file. Channels are grouped by the prefix before their last '.'
// (no prefix: the main layer). A prefix's R, G, B [, A] form its layer, and so do Y [, A] when
// the prefix has no other channels (in the main layer Y becomes grey R = G = B: a luminance file
// gives an RGB image). Every other channel becomes a one-channel layer named by its full channel
// name ("Z", "normal.X"). Half and uint channels are converted to float; pixels outside the data
// window are 0. Metadata holds the string attributes whose names follow the key rule above. A
// missing, unreadable, truncated, deep or non-EXR file throws gib::InputError, and so does one
// whose header declares more than `max_values` values (width × height × channels, of the data
// window as read and of the display window as held): a corrupt or hostile header must not make
// the reader allocate without bound. The default, 2^28 values
// (1 GiB of floats), is far above any image the harness makes (a 4K RGB image is 2^25).
inline constexpr std::size_t kMaxExrValues = std::size_t(1) << 28;
ExrFile readExr(const std::filesystem::path& path, std::size_t max_values = kMaxExrValues);

// What readExr checks before OpenEXR reads a header: the magic number; that every attribute's
// name, type and declared size lie within the file, and that the attributes OpenEXR reads by
// what they hold (fixed-size types, channel lists, previews) hold exactly their declared size, so
// that OpenEXR reads the header where this walk does; and that the data window, channel list and
// tile size, and the display window with the channel list, do not declare more than `max_values`
// values (for every part of a multi-part file).
// OpenEXR allocates by these fields as it opens a file: an attribute at its declared size (found
// by fuzzing: a string attribute of 788 MB in a 976-byte file cost seconds before the read
// failed), its line and tile buffers by the data window and tile size. What the attributes mean
// is left to OpenEXR. Throws gib::InputError.
void checkExrHeader(const std::filesystem::path& path, std::size_t max_values = kMaxExrValues);

// The main layer's R, G and B channels, found by name, as a 3-channel image: alpha and every other
// channel are left out, so an RGBA file (what Blender and most renderers write) reads like the
// same file without alpha, and a luminance file gives grey as in readExr. Throws gib::InputError
// naming the missing channels when the file has no R, G and B (or Y), besides readExr's errors.
Image readRgb(const std::filesystem::path& path, std::size_t max_values = kMaxExrValues);

}  // namespace gib::image
