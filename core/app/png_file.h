#pragma once
// Writing 8-bit RGB pictures as PNG files, the one PNG encoder of both programs: the export's
// developed frames and the preview's snapshots, screenshots and timeline pictures. The same pixels
// always give the same bytes (for one zlib), so a frame rendered on a farm's node is byte for byte
// the frame a local run makes.
#include <cstdint>
#include <string>
#include <vector>

namespace bsim {

/// The 8-bit RGB pixels (three bytes a pixel, rows from the top) as a PNG file's bytes.
std::string encode_png(const std::vector<std::uint8_t>& rgb, int width, int height);

/// Writes the pixels as encode_png does to the PNG at `path`, whole or not at all (atomic_file.h).
/// False with `error` set ("cannot write PATH: REASON") when it fails.
bool write_png(const std::string& path, const std::vector<std::uint8_t>& rgb, int width, int height,
               std::string& error);

}  // namespace bsim
