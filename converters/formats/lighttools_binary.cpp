// LightTools binary ray data ("LTRF"): a 44-byte header, records of 7 or 8 f32, and the 7 bytes
// "LTRFEND". There is no ray count: it follows from the file size. Layout in
// ../shared/formats.md "LightTools ray data"; verified against real LightTools exports.
#include "converters/formats/codecs.h"
#include "converters/formats/lighttools_common.h"
#include "converters/rays/io.h"

#include <fmt/format.h>
#include <algorithm>
#include <cmath>
#include <cstring>

namespace rayset {

namespace {

constexpr char kMagic[4] = {'L', 'T', 'R', 'F'};
constexpr char kTrailer[7] = {'L', 'T', 'R', 'F', 'E', 'N', 'D'};
constexpr uint64_t kHeaderSize = 44;
constexpr uint64_t kTotalFluxOffset = 40;

class LightToolsBinaryDecoder : public RayDecoder {
public:
    explicit LightToolsBinaryDecoder(const std::string& path) : in_(path) { parse_header(); }

    bool decode(RayColumns& chunk, size_t max_rays) override {
        const size_t columns = layout_.columns();
        const size_t n =
            read_f32_records(in_, columns, header_.ray_count, max_rays, next_, buffer_, chunk);
        for (size_t i = 0; i < n; ++i) {
            const float* f = &buffer_[i * columns];
            Ray ray;
            ray.origin = {f[0], f[1], f[2]};
            ray.direction = {f[3], f[4], f[5]};
            set_lighttools_flux(ray, layout_, f[6]);
            if (layout_.wavelength) ray.wavelength = f[7];
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

    uint32_t read_u32(const char* what) { return in_.read<uint32_t>(what); }

    void parse_header() {
        const uint64_t size = in_.size();
        if (size < kHeaderSize + sizeof kTrailer)
            in_.fail_at(0, fmt::format("the file is {} bytes, too short for LightTools ray data (a "
                                       "44-byte header and the 7-byte end marker LTRFEND): it is "
                                       "truncated",
                                       size));
        check_magic_and_version();
        read_layout();
        const LengthUnit unit = read_unit();
        const Vec3f origin = read_origin();
        const float total = in_.read<float>("the total flux");
        if (!std::isfinite(total) || total < 0)
            in_.fail_at(kTotalFluxOffset,
                        fmt::format("total flux {} is not a non-negative number", total));
        const uint64_t rays = count_records(size);
        header_ = lighttools_header(RayFormat::lighttools_binary, layout_, unit, origin, total);
        header_.ray_count = rays;
        in_.seek(kHeaderSize);
    }

    void check_magic_and_version() {
        char magic[4];
        in_.read(magic, sizeof magic, "the LTRF magic");
        if (std::memcmp(magic, kMagic, sizeof magic) != 0)
            in_.fail_at(0, "not LightTools binary ray data: the file does not start with 'LTRF'");
        const uint32_t major = read_u32("the major version");
        if (major == 3)
            in_.fail_at(4,
                        "LightTools ray data version 3 (with polarisation) is not supported: "
                        "export without polarisation (version 2)");
        if (major != 2) in_.fail_at(4, fmt::format("unknown major version {} (expected 2)", major));
        const uint32_t minor = read_u32("the minor version");
        if (minor != 0)
            in_.fail_at(8,
                        fmt::format("unknown minor version {} (only version 2.0 is known)", minor));
    }

    // The data type, far-field flag and colour information: what the flux column holds and
    // whether a wavelength column follows.
    void read_layout() {
        const uint32_t data_type = read_u32("the data type");
        if (data_type > 1)
            in_.fail_at(12, fmt::format("unknown data type {} (expected 0 radiometric or 1 "
                                        "photometric)",
                                        data_type));
        layout_.photometric = data_type == 1;

        const uint32_t far_field = read_u32("the far-field flag");
        // The far-field record layout (whether positions are still stored) is documented nowhere we
        // can check and no sample exists, so guessing could silently misplace every column.
        if (far_field == 1)
            in_.fail_at(16,
                        "far-field LightTools ray data (far-field flag 1 at byte 16) is not "
                        "supported: its record layout is unknown; export near-field rays "
                        "instead");
        if (far_field != 0)
            in_.fail_at(16, fmt::format("invalid far-field flag {} (expected 0 or 1)", far_field));

        const uint32_t colour = read_u32("the colour information");
        if (colour == 1)
            in_.fail_at(20,
                        "tristimulus colour information (colour info 1 at byte 20) is not "
                        "supported: its record layout is unknown; export with wavelength or "
                        "without colour information");
        if (colour != 0 && colour != 2)
            in_.fail_at(20, fmt::format("unknown colour information {} (expected 0 none or 2 "
                                        "wavelength)",
                                        colour));
        layout_.wavelength = colour == 2;
    }

    LengthUnit read_unit() {
        const uint32_t unit_code = read_u32("the length unit");
        // Code 0 is "system units", whatever the LightTools model used; the file does not say
        // which, and LightTools' default system unit is mm, so mm is assumed.
        std::optional<LengthUnit> unit =
            unit_code == 0 ? LengthUnit::mm : lighttools_unit(unit_code);
        if (!unit)
            in_.fail_at(24, fmt::format("unknown length unit code {} (expected 0 system, 1 mm, 2 "
                                        "cm, 3 m, 4 in, 5 ft, 6 um or 7 nm)",
                                        unit_code));
        return *unit;
    }

    Vec3f read_origin() {
        float origin[3];
        in_.read(origin, sizeof origin, "the data origin");
        if (!std::isfinite(origin[0]) || !std::isfinite(origin[1]) || !std::isfinite(origin[2]))
            in_.fail_at(28, fmt::format("data origin ({}, {}, {}) is not finite", origin[0],
                                        origin[1], origin[2]));
        return {origin[0], origin[1], origin[2]};
    }

    // The number of records between the header and the end marker, which must be there.
    uint64_t count_records(uint64_t size) {
        const uint64_t trailer_at = size - sizeof kTrailer;
        char trailer[sizeof kTrailer];
        in_.seek(trailer_at);
        in_.read(trailer, sizeof trailer, "the end marker");
        if (std::memcmp(trailer, kTrailer, sizeof trailer) != 0)
            in_.fail_at(trailer_at,
                        "the file does not end with the end marker LTRFEND: it is "
                        "truncated or damaged");
        const uint64_t body = trailer_at - kHeaderSize;
        if (body % record_bytes() != 0)
            in_.fail_at(kHeaderSize,
                        fmt::format("the {} bytes between the header and LTRFEND are not a whole "
                                    "number of {}-byte ray records (x y z kx ky kz flux{}): the "
                                    "file is damaged",
                                    body, record_bytes(), layout_.wavelength ? " wavelength" : ""));
        return body / record_bytes();
    }

    BinaryInput in_;
    LightToolsLayout layout_;
    uint64_t next_ = 0;
    std::vector<float> buffer_;
};

class LightToolsBinaryEncoder : public RayEncoder {
public:
    LightToolsBinaryEncoder(const std::string& path, const RayHeader& header)
        : out_(path), header_(header) {
        std::optional<LightToolsLayout> layout = lighttools_layout_for(header, dropped_);
        if (!layout)
            fail(path,
                 "cannot write LightTools ray data: the rays carry neither radiant nor luminous "
                 "flux");
        layout_ = *layout;
        note_dropped_descriptions();

        out_.write(kMagic, sizeof kMagic);
        out_.put<uint32_t>(2);  // version 2.0: no polarisation
        out_.put<uint32_t>(0);
        out_.put<uint32_t>(layout_.photometric ? 1 : 0);
        out_.put<uint32_t>(0);  // near field
        out_.put<uint32_t>(layout_.wavelength ? 2 : 0);
        out_.put<uint32_t>(lighttools_unit_code(header.unit));
        out_.put(header.data_origin.x);
        out_.put(header.data_origin.y);
        out_.put(header.data_origin.z);
        out_.put<float>(0);  // total flux, patched by finish()
    }

    void write(const RayChunk& chunk) override {
        const size_t columns = layout_.columns();
        buffer_.resize(chunk.size() * columns);
        for (size_t i = 0; i < chunk.size(); ++i) {
            const Ray& ray = chunk.rays[i];
            const float flux = layout_.photometric ? ray.luminous : ray.radiant;
            const float nm = lighttools_wavelength(header_, ray);
            check_lighttools_ray(out_.path(), written_ + i, flux, layout_.wavelength, nm);
            float* f = &buffer_[i * columns];
            f[0] = ray.origin.x, f[1] = ray.origin.y, f[2] = ray.origin.z;
            f[3] = ray.direction.x, f[4] = ray.direction.y, f[5] = ray.direction.z;
            f[6] = flux;
            if (layout_.wavelength) f[7] = nm;
            sum_ += flux;
        }
        out_.write(buffer_.data(), buffer_.size() * sizeof(float));
        written_ += chunk.size();
    }

    void finish() override {
        out_.write(kTrailer, sizeof kTrailer);
        const double stated =
            layout_.photometric ? header_.stated_luminous : header_.stated_radiant;
        const float total = static_cast<float>(total_to_write(stated, sum_));
        out_.patch(kTotalFluxOffset, &total, sizeof total);
        out_.commit();
    }

private:
    void note_dropped_descriptions() {
        bool any_text = !header_.description.empty() || !header_.creation_date.empty() ||
                        !header_.additional_text.empty();
        for (const std::string& t : header_.text) any_text = any_text || !t.empty();
        if (any_text) dropped_.push_back("descriptive text (the binary format has no text fields)");
    }

    AtomicOutput out_;
    RayHeader header_;
    LightToolsLayout layout_;
    std::vector<float> buffer_;
    uint64_t written_ = 0;
    double sum_ = 0;
};

}  // namespace

bool sniff_lighttools_binary(const Head& head, uint64_t size) {
    return head.size() >= sizeof kMagic && std::memcmp(head.data(), kMagic, sizeof kMagic) == 0;
}

std::unique_ptr<RayDecoder> open_lighttools_binary(const std::string& path) {
    return std::make_unique<LightToolsBinaryDecoder>(path);
}

std::unique_ptr<RayEncoder> create_lighttools_binary(const std::string& path,
                                                     const RayHeader& header) {
    return std::make_unique<LightToolsBinaryEncoder>(path, header);
}

}  // namespace rayset
