// The table of ray-file codecs. Each format implements these three functions in its own
// source file; ray_stream.cpp dispatches on RayFormat. Sniffers look at the first bytes of a
// file (up to 4096) and its size and must not throw.
#pragma once

#include "converters/rays/io.h"
#include "converters/rays/ray_stream.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace rayset {

using Head = std::vector<uint8_t>;

// Shared by the decoders of fixed-size f32 records after a header (LightTools binary, Zemax
// binary, SPEOS): clears `chunk` and sets its first index, reads the next records (at most
// max_rays, none past `count`) of `columns` floats each into `records`, sizes `chunk` to
// match and advances `next`. Returns the number of records read, 0 at the end.
size_t read_f32_records(BinaryInput& in, size_t columns, uint64_t count, size_t max_rays,
                        uint64_t& next, std::vector<float>& records, RayColumns& chunk);

bool sniff_tm25(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_tm25(const std::string& path);
std::unique_ptr<RayEncoder> create_tm25(const std::string& path, const RayHeader& header);

bool sniff_lighttools_binary(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_lighttools_binary(const std::string& path);
std::unique_ptr<RayEncoder> create_lighttools_binary(const std::string& path,
                                                     const RayHeader& header);

bool sniff_lighttools_text(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_lighttools_text(const std::string& path);
std::unique_ptr<RayEncoder> create_lighttools_text(const std::string& path,
                                                   const RayHeader& header);

bool sniff_zemax_binary(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_zemax_binary(const std::string& path);
std::unique_ptr<RayEncoder> create_zemax_binary(const std::string& path, const RayHeader& header);

bool sniff_zemax_text(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_zemax_text(const std::string& path);
std::unique_ptr<RayEncoder> create_zemax_text(const std::string& path, const RayHeader& header);

bool sniff_speos(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_speos(const std::string& path);
std::unique_ptr<RayEncoder> create_speos(const std::string& path, const RayHeader& header);

bool sniff_csv(const Head& head, uint64_t size);
std::unique_ptr<RayDecoder> open_csv(const std::string& path);
std::unique_ptr<RayEncoder> create_csv(const std::string& path, const RayHeader& header);

}  // namespace rayset
