// SPEOS binary .ray: a 28-byte header of 7 f32 (radiant total W, five values that are 2.0 in
// every file seen, luminous total lm) and records of 8 f32: x y z l m n wavelength(nm) E, E a
// relative radiant weight. No magic and no count: the size gives the count. Layout in
// ../shared/formats.md "SPEOS .ray"; verified on the ansys/optical-automation test files.
#include "converters/colour/spectrum.h"
#include "converters/formats/codecs.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstring>

namespace rayset {

namespace {

constexpr uint64_t kHeaderSize = 28;
constexpr uint64_t kRecordSize = 32;
constexpr uint64_t kLuminousAt = 24;
// Their meaning is unknown; every real file holds 2.0 in each, so they are treated as part of
// the format (the sniffer's only evidence besides the size) and written back as 2.0.
constexpr float kConstant = 2.0f;
constexpr size_t kConstants = 5;

float header_float(const uint8_t* bytes, size_t index) {
    float v;
    std::memcpy(&v, bytes + 4 * index, sizeof v);
    return v;
}

class SpeosDecoder : public RayDecoder {
public:
    explicit SpeosDecoder(const std::string& path) : in_(path) { parse_header(); }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        const size_t columns = 8;
        const size_t n =
            read_f32_records(in_, columns, header_.ray_count, max_rays, next_, buffer_, chunk);
        for (size_t i = 0; i < n; ++i) {
            const float* f = &buffer_[i * columns];
            Ray ray;
            ray.origin = {f[0], f[1], f[2]};
            ray.direction = {f[3], f[4], f[5]};
            ray.wavelength = f[6];
            ray.radiant = f[7];
            chunk.set(i, ray);
        }
        return n > 0;
    }

    Location locate(uint64_t index) const override {
        return Location::byte(kHeaderSize + index * kRecordSize);
    }
    bool can_seek() const override { return true; }
    void seek(uint64_t index) override { in_.seek(locate(index).value), next_ = index; }
    bool flux_is_relative() const override { return true; }

private:
    void parse_header() {
        const uint64_t size = in_.size();
        if (size < kHeaderSize || (size - kHeaderSize) % kRecordSize != 0) {
            const uint64_t body = size < kHeaderSize ? 0 : size - kHeaderSize;
            in_.fail_at(std::min(size, kHeaderSize + body / kRecordSize * kRecordSize),
                        fmt::format("the file is {} bytes, not a 28-byte SPEOS header plus whole "
                                    "32-byte rays ({} bytes "
                                    "left over): it is truncated or not a SPEOS ray file",
                                    size, size < kHeaderSize ? size : body % kRecordSize));
        }
        uint8_t h[kHeaderSize];
        in_.read(h, kHeaderSize, "the 28-byte SPEOS header");
        for (size_t i = 1; i <= kConstants; ++i) {
            const float v = header_float(h, i);
            if (v != kConstant)
                in_.fail_at(
                    4 * i,
                    fmt::format(
                        "header value {} is {}, but it is 2.0 in every SPEOS ray file known; its "
                        "meaning is unknown, so this file cannot be read safely",
                        i + 1, v));
        }
        const float radiant = header_float(h, 0), luminous = header_float(h, 6);
        if (!(std::isfinite(radiant) && radiant >= 0))
            in_.fail_at(0, fmt::format("radiant total {} W is not a non-negative number", radiant));
        if (!(std::isfinite(luminous) && luminous >= 0))
            in_.fail_at(kLuminousAt,
                        fmt::format("luminous total {} lm is not a non-negative number", luminous));

        header_.format = RayFormat::speos;
        header_.unit = LengthUnit::mm;
        header_.ray_count = (size - kHeaderSize) / kRecordSize;
        header_.has_radiant = true;
        header_.stated_radiant = radiant;
        header_.stated_luminous = luminous;
        header_.spectral = SpectralKind::per_ray_wavelength;
    }

    BinaryInput in_;
    uint64_t next_ = 0;
    std::vector<float> buffer_;
};

class SpeosEncoder : public RayEncoder {
public:
    SpeosEncoder(const std::string& path, const RayHeader& header)
        : out_(path), header_(header), scale_(millimetres_per(header.unit)) {
        if (!header.has_radiant)
            fail(path,
                 "cannot write SPEOS rays: their weights are radiant and these rays carry no "
                 "radiant flux "
                 "(convert luminous rays through a format that keeps them, e.g. TM-25)");
        if (header.spectral != SpectralKind::per_ray_wavelength &&
            header.spectral != SpectralKind::single_wavelength)
            fail(path,
                 "cannot write SPEOS rays: every SPEOS ray needs a wavelength and these rays have "
                 "none "
                 "(no per-ray or single wavelength in the source file)");
        if (header.has_luminous)
            dropped_.push_back("per-ray luminous flux (SPEOS keeps radiant weights)");
        if (!header.extras.empty())
            dropped_.push_back("extra per-ray columns (" + std::to_string(header.extras.size()) +
                               ")");
        if (header.unit != LengthUnit::mm)
            dropped_.push_back(std::string("length unit ") + to_string(header.unit) +
                               " (SPEOS rays are in mm: positions converted)");
        float h[7] = {0, kConstant, kConstant, kConstant, kConstant, kConstant, 0};
        out_.write(h, sizeof h);
    }

    void write(const RayChunk& chunk) override {
        buffer_.resize(chunk.rays.size() * 8);
        for (size_t i = 0; i < chunk.rays.size(); ++i) {
            const Ray& ray = chunk.rays[i];
            const float nm = header_.spectral == SpectralKind::single_wavelength
                                 ? header_.single_wavelength
                                 : ray.wavelength;
            const uint64_t index = written_ + i;
            if (!std::isfinite(ray.radiant) || ray.radiant < 0)
                fail(out_.path(), fmt::format("ray {}: radiant flux {} cannot be written: SPEOS "
                                              "needs a non-negative weight "
                                              "for every ray",
                                              index + 1, ray.radiant));
            if (!(std::isfinite(nm) && nm > 0))
                fail(out_.path(), fmt::format("ray {}: wavelength {} nm cannot be written: SPEOS "
                                              "needs a known wavelength "
                                              "for every ray",
                                              index + 1, nm));
            float* f = &buffer_[i * 8];
            f[0] = scaled(ray.origin.x);
            f[1] = scaled(ray.origin.y);
            f[2] = scaled(ray.origin.z);
            f[3] = ray.direction.x;
            f[4] = ray.direction.y;
            f[5] = ray.direction.z;
            f[6] = nm;
            f[7] = ray.radiant;
            radiant_ += ray.radiant;
            // Each ray is monochromatic, so its luminous flux is its radiant weight times 683
            // V(lambda).
            luminous_ += kMaxLuminousEfficacy * photopic_efficiency(nm) * ray.radiant;
        }
        out_.write(buffer_.data(), buffer_.size() * sizeof(float));
        written_ += chunk.rays.size();
    }

    // Totals: the stated ones when the rays agree with them; otherwise the rays' radiant sum and
    // the luminous flux V(lambda) gives those rays (SPEOS has no "unknown" total).
    void finish() override {
        const float radiant = float(total_to_write(header_.stated_radiant, radiant_));
        const bool stated = totals_agree(header_.stated_radiant, radiant_) &&
                            std::isfinite(header_.stated_luminous);
        const float luminous = float(stated ? header_.stated_luminous : luminous_);
        out_.patch(0, &radiant, sizeof radiant);
        out_.patch(kLuminousAt, &luminous, sizeof luminous);
        out_.commit();
    }

private:
    float scaled(float v) const { return scale_ == 1 ? v : float(v * scale_); }

    AtomicOutput out_;
    RayHeader header_;
    double scale_;
    std::vector<float> buffer_;
    uint64_t written_ = 0;
    double radiant_ = 0, luminous_ = 0;
};

}  // namespace

// No magic: strict so that it never claims another format's file. The size must be the header
// plus whole records and the five constant header values must be exactly 2.0.
bool sniff_speos(const Head& head, uint64_t size) {
    if (size < kHeaderSize || (size - kHeaderSize) % kRecordSize != 0 || head.size() < kHeaderSize)
        return false;
    for (size_t i = 1; i <= kConstants; ++i)
        if (header_float(head.data(), i) != kConstant) return false;
    return true;
}

std::unique_ptr<RayDecoder> open_speos(const std::string& path) {
    return std::make_unique<SpeosDecoder>(path);
}

std::unique_ptr<RayEncoder> create_speos(const std::string& path, const RayHeader& header) {
    return std::make_unique<SpeosEncoder>(path, header);
}

}  // namespace rayset
