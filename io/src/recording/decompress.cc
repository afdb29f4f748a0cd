#include "recording/decompress.h"

#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <algorithm>
#include <memory>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io::recording {
namespace {

using model::InputError;

std::string Bz2(std::string_view data, std::size_t size, const std::string& where) {
  std::string out(size, '\0');
  unsigned int out_size = static_cast<unsigned int>(size);
  const int rc = BZ2_bzBuffToBuffDecompress(out.data(), &out_size, const_cast<char*>(data.data()),
                                            static_cast<unsigned int>(data.size()), 0, 0);
  if (rc != BZ_OK || out_size != size) {
    throw InputError(where, "expected a bz2 chunk of " + std::to_string(size) +
                                " bytes, got bzip2 error " + std::to_string(rc));
  }
  return out;
}

std::string Lz4(std::string_view data, std::size_t size, const std::string& where) {
  LZ4F_dctx* raw = nullptr;
  if (LZ4F_isError(LZ4F_createDecompressionContext(&raw, LZ4F_VERSION))) {
    throw InputError(where, "expected an lz4 decompression context (out of memory)");
  }
  std::unique_ptr<LZ4F_dctx, decltype(&LZ4F_freeDecompressionContext)> ctx(
      raw, &LZ4F_freeDecompressionContext);
  std::string out(size, '\0');
  std::size_t in_pos = 0, out_pos = 0;
  while (in_pos < data.size()) {
    std::size_t in_n = data.size() - in_pos, out_n = size - out_pos;
    const std::size_t rc = LZ4F_decompress(ctx.get(), out.data() + out_pos, &out_n,
                                           data.data() + in_pos, &in_n, nullptr);
    if (LZ4F_isError(rc)) {
      throw InputError(where, std::string("expected an lz4 frame, got: ") + LZ4F_getErrorName(rc));
    }
    in_pos += in_n;
    out_pos += out_n;
    if (in_n == 0 && out_n == 0) break;
  }
  if (out_pos != size) {
    throw InputError(where, "expected an lz4 chunk of " + std::to_string(size) + " bytes, got " +
                                std::to_string(out_pos));
  }
  return out;
}

std::string Zstd(std::string_view data, std::size_t size, const std::string& where) {
  std::string out(size, '\0');
  const std::size_t rc = ZSTD_decompress(out.data(), size, data.data(), data.size());
  if (ZSTD_isError(rc) || rc != size) {
    throw InputError(where, "expected a zstd chunk of " + std::to_string(size) + " bytes, got " +
                                (ZSTD_isError(rc) ? ZSTD_getErrorName(rc) : std::to_string(rc)));
  }
  return out;
}

}  // namespace

std::string Decompressed(std::string_view data, const std::string& compression, std::size_t size,
                         const std::string& where) {
  // A size no compression reaches is a corrupt field: LZ4 expands at most 255-fold (its
  // format's limit); bz2 and zstd are held to 4096-fold, beyond any recorded messages.
  const std::size_t ratio = compression == "lz4" ? 255 : 4096;
  const std::size_t limit = std::min(std::size_t(1) << 31, (data.size() + 1024) * ratio);
  if (size > limit) {
    throw InputError(where, "expected a chunk size its " + std::to_string(data.size()) +
                                " compressed bytes can hold, got " + std::to_string(size));
  }
  if (compression.empty() || compression == "none") {
    if (data.size() != size) {
      throw InputError(where, "expected a stored chunk of " + std::to_string(size) +
                                  " bytes, got " + std::to_string(data.size()));
    }
    return std::string(data);
  }
  if (compression == "bz2") return Bz2(data, size, where);
  if (compression == "lz4") return Lz4(data, size, where);
  if (compression == "zstd") return Zstd(data, size, where);
  throw InputError(where,
                   "expected chunk compression none, bz2, lz4 or zstd, got '" + compression + "'");
}

}  // namespace uuvplan::io::recording
