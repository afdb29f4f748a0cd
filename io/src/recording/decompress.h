// The compressions of ROS bag chunks (bz2, lz4 frames as roslz4 writes them) and MCAP chunks
// (lz4 frames, zstd), through libbz2, liblz4 (LZ4F) and libzstd.
#pragma once

#include <string>
#include <string_view>

namespace uuvplan::io::recording {

/// `data` decompressed by `compression` ("none" or "" = stored, "bz2", "lz4", "zstd") into
/// exactly `size` bytes; anything else is model::InputError naming `where`.
std::string Decompressed(std::string_view data, const std::string& compression, std::size_t size,
                         const std::string& where);

}  // namespace uuvplan::io::recording
