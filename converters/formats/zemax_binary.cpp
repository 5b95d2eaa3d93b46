// Zemax OpticStudio binary source file (.DAT flux only, .SDF spectral): a 208-byte header and
// records of 7 or 8 f32. Layout in ../shared/formats.md "Zemax OpticStudio source file";
// verified against files written by OpticStudio-compatible tools (ansys/optical-automation,
// TM25RaySetTools).
#include "converters/formats/codecs.h"
#include "converters/formats/zemax_common.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstring>

namespace rayset {

namespace {

constexpr int32_t kIdentifier = 1010;
constexpr uint64_t kHeaderSize = 208;
constexpr size_t kDescriptionSize = 100;

// Byte offsets of the header fields.
enum : size_t {
    kCountAt = 4,
    kDescriptionAt = 8,
    kSourceFluxAt = 108,
    kRaySetFluxAt = 112,
    kWavelengthAt = 116,
    kAnglesAt = 120,  // inclination begin/end, azimuth begin/end (deg)
    kUnitsAt = 136,
    kLocationAt = 140,
    kRotationAt = 152,
    kScaleAt = 164,
    kRayFormatAt = 192,
    kFluxTypeAt = 196,
};

template <class T>
T get(const uint8_t* header, size_t at) {
    T value;
    std::memcpy(&value, header + at, sizeof value);
    return value;
}

template <class T>
void put(uint8_t* header, size_t at, T value) {
    std::memcpy(header + at, &value, sizeof value);
}

Vec3f get_vec(const uint8_t* header, size_t at) {
    return {get<float>(header, at), get<float>(header, at + 4), get<float>(header, at + 8)};
}

void put_vec(uint8_t* header, size_t at, const Vec3f& v) {
    put(header, at, v.x);
    put(header, at + 4, v.y);
    put(header, at + 8, v.z);
}

class ZemaxBinaryDecoder : public RayDecoder {
public:
    explicit ZemaxBinaryDecoder(const std::string& path) : in_(path) { parse_header(); }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        const size_t columns = layout_.columns();
        const size_t n =
            read_f32_records(in_, columns, header_.ray_count, max_rays, next_, buffer_, chunk);
        for (size_t i = 0; i < n; ++i) {
            const float* f = &buffer_[i * columns];
            Ray ray;
            ray.origin = {f[0], f[1], f[2]};
            ray.direction = {f[3], f[4], f[5]};
            set_zemax_flux(ray, layout_, f[6]);
            if (layout_.wavelength) ray.wavelength = zemax_um_to_nm(f[7]);
            chunk.set(i, ray);
        }
        return n > 0;
    }

    Location locate(uint64_t index) const override {
        return Location::byte(kHeaderSize + index * record_bytes());
    }
    bool can_seek() const override { return true; }
    void seek(uint64_t index) override { in_.seek(locate(index).value), next_ = index; }
    bool flux_is_relative() const override { return true; }

private:
    uint64_t record_bytes() const { return layout_.columns() * sizeof(float); }

    void parse_header() {
        uint8_t h[kHeaderSize];
        in_.read(h, kHeaderSize, "the 208-byte Zemax header");
        const int32_t identifier = get<int32_t>(h, 0);
        if (identifier != kIdentifier)
            in_.fail_at(
                0,
                fmt::format(
                    "identifier {} is not 1010: not a Zemax source file (or a version of it this "
                    "reader does not know)",
                    identifier));
        const uint32_t units = get<uint32_t>(h, kUnitsAt);
        const auto unit = zemax_unit(units);
        if (!unit)
            in_.fail_at(
                kUnitsAt,
                fmt::format(
                    "dimension units code {} is not a Zemax unit (0 m, 1 in, 2 cm, 3 ft, 4 mm)",
                    units));
        layout_ = zemax_layout(
            get<int32_t>(h, kRayFormatAt), get<int32_t>(h, kFluxTypeAt),
            [&](const std::string& what) { in_.fail_at(kRayFormatAt, what); },
            [&](const std::string& what) { in_.fail_at(kFluxTypeAt, what); });
        header_ = zemax_header(RayFormat::zemax_binary, layout_, *unit);

        const float source_flux = get<float>(h, kSourceFluxAt);
        if (!std::isnan(source_flux) && !(std::isfinite(source_flux) && source_flux >= 0))
            in_.fail_at(kSourceFluxAt,
                        fmt::format("source flux {} is not a non-negative number", source_flux));
        (layout_.lumens ? header_.stated_luminous : header_.stated_radiant) = source_flux;
        // OpticStudio ignores the ray-set flux; it is kept as written, whatever it holds.
        header_.ray_set_flux = get<float>(h, kRaySetFluxAt);
        parse_wavelength(get<float>(h, kWavelengthAt));

        const char* text = reinterpret_cast<const char*>(h + kDescriptionAt);
        std::string description(text, strnlen(text, kDescriptionSize));
        // Writers pad the field with spaces as often as with NULs.
        while (!description.empty() && description.back() == ' ') description.pop_back();
        header_.description = description;

        SourcePlacement& p = header_.placement;
        for (size_t i = 0; i < 4; ++i)
            p.inclination_azimuth_deg[i] = get<float>(h, kAnglesAt + 4 * i);
        p.location = get_vec(h, kLocationAt);
        p.rotation_rad = get_vec(h, kRotationAt);
        p.scale = get_vec(h, kScaleAt);

        header_.ray_count = get<uint32_t>(h, kCountAt);
        check_size();
    }

    // The header wavelength means something only for flux-only files: 0 composite, else every
    // ray's wavelength. Spectral files carry theirs per ray and OpticStudio ignores this field
    // (NaN is seen there in real files).
    void parse_wavelength(float um) {
        if (layout_.wavelength || um == 0 || std::isnan(um)) return;
        if (!(std::isfinite(um) && um > 0))
            in_.fail_at(
                kWavelengthAt,
                fmt::format("wavelength {} um is not a positive number (0 would mean composite)",
                            um));
        header_.spectral = SpectralKind::single_wavelength;
        header_.single_wavelength = zemax_um_to_nm(um);
    }

    // The count must match the file size exactly: a shorter file is truncated, a longer one has
    // rays (or garbage) the count does not cover, and guessing which would drop or invent rays.
    void check_size() {
        const uint64_t count = header_.ray_count, record = record_bytes();
        const uint64_t size = in_.size(), body = size - kHeaderSize, need = count * record;
        if (body == need) return;
        const std::string stated = fmt::format(
            "the header (byte 4) states {} rays of {} bytes = {} bytes after the 208-byte header",
            count, record, need);
        if (body < need && body % record != 0) {
            const uint64_t whole = body / record;
            in_.fail_at(kHeaderSize + whole * record,
                        fmt::format("ray {} is cut off after {} of its {} bytes: the file is {} "
                                    "bytes, {} bytes after "
                                    "the header, but {}: the file is truncated",
                                    whole + 1, body % record, record, size, body, stated));
        }
        if (body < need)
            in_.fail_at(
                kCountAt,
                fmt::format(
                    "{}, but the file is {} bytes, {} bytes (= {} rays) after the header: the "
                    "file is truncated or the count is wrong",
                    stated, size, body, body / record));
        const uint64_t extra = body - need;
        in_.fail_at(
            kHeaderSize + need,
            fmt::format("{} bytes follow the last ray: {}, but the file is {} bytes{}", extra,
                        stated, size,
                        extra % record == 0
                            ? fmt::format(" (room for {} more {}: the count may be wrong)",
                                          extra / record, extra / record == 1 ? "ray" : "rays")
                            : std::string()));
    }

    BinaryInput in_;
    ZemaxLayout layout_;
    uint64_t next_ = 0;
    std::vector<float> buffer_;
};

class ZemaxBinaryEncoder : public RayEncoder {
public:
    ZemaxBinaryEncoder(const std::string& path, const RayHeader& header)
        : out_(path), header_(header) {
        layout_ = zemax_layout_for(path, header, true, dropped_);
        unit_ = zemax_unit_for(header.unit, dropped_);
        if (std::isfinite(layout_.lumens ? header.stated_radiant : header.stated_luminous))
            dropped_.push_back(layout_.lumens
                                   ? "stated radiant total (Zemax states one total: lumens here)"
                                   : "stated luminous total (Zemax states one total: watts here)");
        write_header();
    }

    void write(const RayChunk& chunk) override {
        const size_t columns = layout_.columns();
        check_zemax_count(out_.path(), written_ + chunk.rays.size());
        buffer_.resize(chunk.rays.size() * columns);
        for (size_t i = 0; i < chunk.rays.size(); ++i) {
            const Ray& ray = chunk.rays[i];
            const float flux = zemax_flux(ray, layout_);
            const float nm = zemax_ray_nm(header_, ray);
            check_zemax_ray(out_.path(), written_ + i, flux, layout_.wavelength, nm);
            float* f = &buffer_[i * columns];
            f[0] = scaled(ray.origin.x);
            f[1] = scaled(ray.origin.y);
            f[2] = scaled(ray.origin.z);
            f[3] = ray.direction.x;
            f[4] = ray.direction.y;
            f[5] = ray.direction.z;
            f[6] = flux;
            if (layout_.wavelength) f[7] = zemax_nm_to_um(nm);
            sum_ += flux;
        }
        out_.write(buffer_.data(), buffer_.size() * sizeof(float));
        written_ += chunk.rays.size();
    }

    void finish() override {
        const uint32_t count = static_cast<uint32_t>(written_);
        out_.patch(kCountAt, &count, sizeof count);
        const double stated = layout_.lumens ? header_.stated_luminous : header_.stated_radiant;
        const float source = float(total_to_write(stated, sum_));
        // The ray-set flux is kept only beside the total it was stated with.
        const bool kept = totals_agree(stated, sum_) && std::isfinite(header_.ray_set_flux);
        const float ray_set = kept ? float(header_.ray_set_flux) : source;
        out_.patch(kSourceFluxAt, &source, sizeof source);
        out_.patch(kRaySetFluxAt, &ray_set, sizeof ray_set);
        out_.commit();
    }

private:
    float scaled(float v) const { return unit_.scale == 1 ? v : float(v * unit_.scale); }

    void write_header() {
        uint8_t h[kHeaderSize] = {};
        put(h, 0, kIdentifier);
        std::string description = header_.description;
        if (description.size() >= kDescriptionSize) {
            dropped_.push_back(
                fmt::format("description beyond its first {} bytes", kDescriptionSize - 1));
            description.resize(kDescriptionSize - 1);  // a NUL ends it for C readers
        }
        std::memcpy(h + kDescriptionAt, description.data(), description.size());
        float um = 0;  // composite
        if (!layout_.wavelength && header_.spectral == SpectralKind::single_wavelength &&
            std::isfinite(header_.single_wavelength))
            um = zemax_nm_to_um(header_.single_wavelength);
        put(h, kWavelengthAt, um);
        const SourcePlacement& p = header_.placement;
        for (size_t i = 0; i < 4; ++i) put(h, kAnglesAt + 4 * i, p.inclination_azimuth_deg[i]);
        put(h, kUnitsAt, unit_.code);
        put_vec(h, kLocationAt, p.location);
        put_vec(h, kRotationAt, p.rotation_rad);
        put_vec(h, kScaleAt, p.scale);
        put(h, kRayFormatAt, layout_.ray_format());
        put(h, kFluxTypeAt, layout_.flux_type());
        out_.write(h, sizeof h);
    }

    AtomicOutput out_;
    RayHeader header_;
    ZemaxLayout layout_;
    ZemaxUnit unit_;
    std::vector<float> buffer_;
    uint64_t written_ = 0;
    double sum_ = 0;
};

}  // namespace

bool sniff_zemax_binary(const Head& head, uint64_t size) {
    // The identifier alone: a wrong count or code is better reported by the decoder than by
    // "no format fits". As the first f32 of a SPEOS file, 1010 would be a 1e-42 W denormal.
    return head.size() >= 4 && get<int32_t>(head.data(), 0) == kIdentifier;
}

std::unique_ptr<RayDecoder> open_zemax_binary(const std::string& path) {
    return std::make_unique<ZemaxBinaryDecoder>(path);
}

std::unique_ptr<RayEncoder> create_zemax_binary(const std::string& path, const RayHeader& header) {
    return std::make_unique<ZemaxBinaryEncoder>(path, header);
}

}  // namespace rayset
