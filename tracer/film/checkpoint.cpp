// Writing and reading render checkpoints (format in checkpoint.h).
#include "tracer/film/checkpoint.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <variant>

#include <fmt/format.h>
#include <unistd.h>

#include "core/error.h"
#include "tracer/film/staged_files.h"

static_assert(__BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__,
              "checkpoints are written in the host's byte order");

namespace rayset::tracer {

namespace {

constexpr char kMagic[8] = {'R', 'A', 'Y', 'S', 'E', 'T', 'C', 'K'};

struct Fnv1a {
    uint64_t value = 0xCBF29CE484222325ULL;
    void add(const void* data, size_t size) {
        const auto* bytes = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < size; ++i) value = (value ^ bytes[i]) * 0x100000001B3ULL;
    }
    void add(const std::string& text) { add(text.data(), text.size()); }
};

class Writer {
public:
    template <typename T>
    void put(T value) {
        static_assert(std::is_arithmetic_v<T>);
        const size_t at = bytes_.size();
        bytes_.resize(at + sizeof(T));
        std::memcpy(bytes_.data() + at, &value, sizeof(T));
    }
    void put(const std::string& text) {
        put(uint32_t(text.size()));
        bytes_.insert(bytes_.end(), text.begin(), text.end());
    }
    void put(const SampleGrid& grid) {
        put(uint32_t(grid.nx())), put(uint32_t(grid.ny())), put(uint32_t(grid.samples()));
        for (const Rgb& s : grid.sums()) put(s.red), put(s.green), put(s.blue);
        for (double q : grid.photometric_squares()) put(q);
    }
    void put(const Film& film, const std::vector<ReceiverMap>& receivers) {
        put(film);
        put(uint32_t(receivers.size()));
        for (const ReceiverMap& map : receivers) put(map.receiver.name), put(map.irradiance);
    }
    std::string& bytes() { return bytes_; }

private:
    std::string bytes_;
};

// Reads what Writer wrote; every read past the end is a truncated file.
class Reader {
public:
    Reader(const std::string& bytes, const std::string& path) : bytes_(bytes), path_(path) {}
    template <typename T>
    T get() {
        T value;
        std::memcpy(&value, take(sizeof(T)), sizeof(T));
        return value;
    }
    std::string get_string() {
        const uint32_t size = get<uint32_t>();
        return std::string(take(size), size);
    }
    // A grid stored as `expected` is laid out (the same scene and settings).
    SampleGrid get_grid(const SampleGrid& expected, const std::string& what) {
        const int nx = int(get<uint32_t>()), ny = int(get<uint32_t>());
        const size_t samples_at = position_;
        const uint32_t samples = get<uint32_t>();
        // Each pass adds one sample to every cell, and passes are counted in an int.
        if (samples > uint32_t(std::numeric_limits<int>::max()))
            throw Error(fmt::format(
                "{}: byte {}: {} counts {} samples, more than a render takes (at most {}): the "
                "checkpoint is corrupt",
                path_, samples_at, what, samples, std::numeric_limits<int>::max()));
        if (nx != expected.nx() || ny != expected.ny())
            fail(fmt::format("{} has {} x {} cells, this render {} x {}", what, nx, ny,
                             expected.nx(), expected.ny()));
        std::vector<Rgb> sums(size_t(nx) * ny);
        std::vector<double> squares(sums.size());
        for (Rgb& s : sums) s.red = get<double>(), s.green = get<double>(), s.blue = get<double>();
        for (double& q : squares) q = get<double>();
        return SampleGrid::restored(nx, ny, int(samples), std::move(sums), std::move(squares));
    }
    void get_grids(Film& film, std::vector<ReceiverMap>& receivers, const std::string& what) {
        film = get_grid(film, what + "image");
        const uint32_t count = get<uint32_t>();
        if (count != receivers.size())
            fail(fmt::format("{} receivers in the checkpoint, {} in the scene", count,
                             receivers.size()));
        for (ReceiverMap& map : receivers) {
            const std::string name = get_string();
            if (name != map.receiver.name)
                fail(fmt::format("receiver '{}' in the checkpoint where the scene has '{}'", name,
                                 map.receiver.name));
            map.irradiance = get_grid(map.irradiance, what + "receiver " + name);
        }
    }
    void skip(size_t size) { take(size); }
    bool at_end() const { return position_ == bytes_.size(); }
    [[noreturn]] void fail(const std::string& why) const {
        throw Error(fmt::format("{}: the checkpoint does not fit this render: {}", path_, why));
    }

private:
    const char* take(size_t size) {
        if (size > bytes_.size() - position_)
            throw Error(fmt::format("{}: truncated checkpoint", path_));
        const char* at = bytes_.data() + position_;
        position_ += size;
        return at;
    }
    const std::string& bytes_;
    const std::string& path_;
    size_t position_ = 0;
};

void put_identity(Writer& out, const CheckpointIdentity& id) {
    out.put(id.scene), out.put(id.scene_hash), out.put(uint32_t(id.width)),
        out.put(uint32_t(id.height));
    out.put(id.seed), out.put(id.integrator), out.put(uint8_t(id.render_image)),
        out.put(uint32_t(id.photons_per_pass));
    out.put(id.photon_radius), out.put(uint8_t(id.naive_sources));
}

CheckpointIdentity get_identity(Reader& in) {
    CheckpointIdentity id;
    id.scene = in.get_string(), id.scene_hash = in.get<uint64_t>();
    id.width = int(in.get<uint32_t>()), id.height = int(in.get<uint32_t>());
    id.seed = in.get<uint64_t>(), id.integrator = in.get_string(),
    id.render_image = in.get<uint8_t>() != 0;
    id.photons_per_pass = int(in.get<uint32_t>()), id.photon_radius = in.get<double>();
    id.naive_sources = in.get<uint8_t>() != 0;
    return id;
}

// "seed 7 (this render: 0)" for every field that differs.
std::vector<std::string> differences(const CheckpointIdentity& stored,
                                     const CheckpointIdentity& now) {
    std::vector<std::string> d;
    auto compare = [&](const char* what, const auto& a, const auto& b) {
        if (a != b) d.push_back(fmt::format("{} {} (this render: {})", what, a, b));
    };
    if (stored.scene_hash != now.scene_hash)
        d.push_back(fmt::format(
            "scene {} with content hash {:016x} (this render: {} with hash {:016x}; the scene, "
            "an included file or a data file changed)",
            stored.scene, stored.scene_hash, now.scene, now.scene_hash));
    compare("width", stored.width, now.width);
    compare("height", stored.height, now.height);
    compare("seed", stored.seed, now.seed);
    compare("integrator", stored.integrator, now.integrator);
    compare("image rendered", stored.render_image, now.render_image);
    compare("photons per pass", stored.photons_per_pass, now.photons_per_pass);
    compare("first photon radius", stored.photon_radius, now.photon_radius);
    compare("naive sources", stored.naive_sources, now.naive_sources);
    return d;
}

std::string read_whole_file(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("{}: cannot open the checkpoint", path));
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw Error(fmt::format("{}: cannot read the checkpoint", path));
    return bytes;
}

}  // namespace

uint64_t scene_content_hash(const SceneDescription& scene) {
    Fnv1a hash;
    for (const std::string& file : scene.files) {
        std::ifstream in(file, std::ios::binary);
        if (!in) throw Error(fmt::format("{}: cannot read the scene file to identify it", file));
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        const uint64_t size = text.size();
        hash.add(&size, sizeof size);
        hash.add(text);
    }
    // Data files can be large: their path and size stand for their content.
    std::vector<std::string> data;
    for (const RaySource& source : scene.ray_sources) data.push_back(source.path);
    for (const ObjectInstance& object : scene.objects)
        if (const auto* mesh = std::get_if<MeshFileShape>(&object.shape))
            data.push_back(mesh->path);
    for (const std::string& file : data) {
        std::error_code error;
        const uint64_t size = std::filesystem::file_size(file, error);
        if (error)
            throw Error(
                fmt::format("{}: cannot read the size of the data file to identify it", file));
        hash.add(file);
        hash.add(&size, sizeof size);
    }
    return hash.value;
}

CheckpointIdentity checkpoint_identity(const SceneDescription& scene,
                                       const RenderSettings& settings) {
    CheckpointIdentity id;
    id.scene = scene.files.empty() ? std::string() : scene.files.front();
    id.scene_hash = scene_content_hash(scene);
    id.width = settings.width, id.height = settings.height;
    id.seed = settings.seed;
    id.integrator = scene.global.integrator;
    // Spectral transport is a variant of its integrator (--spectral; the scene's
    // `spectral on` is in its hash already): named with it, the file format stays as it is.
    if (settings.spectral) id.integrator += " spectral";
    id.render_image = settings.render_image;
    id.photons_per_pass = settings.photons_per_pass;
    id.photon_radius = settings.photon_radius;
    id.naive_sources = settings.naive_sources;
    return id;
}

void write_checkpoint(const std::string& path, const CheckpointIdentity& identity,
                      const RenderResult& state) {
    Writer out;
    for (char c : kMagic) out.put(c);
    out.put(kCheckpointVersion);
    put_identity(out, identity);
    out.put(uint32_t(state.passes)), out.put(state.seconds), out.put(state.rays),
        out.put(state.photons);
    out.put(state.photon_radius), out.put(uint64_t(state.photon_bytes)),
        out.put(uint64_t(state.visible_point_bytes));
    out.put(state.film, state.receivers);
    out.put(uint32_t(state.layers.size()));
    for (const RenderLayer& layer : state.layers)
        out.put(layer.name), out.put(layer.film, layer.receivers);
    Fnv1a hash;
    hash.add(out.bytes());
    out.put(hash.value);

    StagedFiles files;
    const std::string temporary = files.stage(path);
    std::FILE* file = std::fopen(temporary.c_str(), "wb");
    if (!file) throw Error(fmt::format("{}: cannot create the checkpoint", path));
    bool ok = std::fwrite(out.bytes().data(), 1, out.bytes().size(), file) == out.bytes().size();
    // On disk before the rename, so that even a crash of the machine leaves a whole file.
    ok = std::fflush(file) == 0 && fsync(fileno(file)) == 0 && ok;
    if (std::fclose(file) != 0 || !ok)
        throw Error(fmt::format("{}: cannot write the checkpoint", path));
    files.commit();
}

RenderResult read_checkpoint(const std::string& path, const CheckpointIdentity& expected,
                             RenderResult blank) {
    const std::string bytes = read_whole_file(path);
    if (bytes.size() < sizeof kMagic || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        throw Error(fmt::format("{}: not a raytrace checkpoint", path));
    Reader in(bytes, path);
    in.skip(sizeof kMagic);
    const uint32_t version = in.get<uint32_t>();
    if (version != kCheckpointVersion)
        throw Error(fmt::format(
            "{}: checkpoint format version {}; this raytrace reads version {} only (render "
            "afresh, without --resume)",
            path, version, kCheckpointVersion));
    if (bytes.size() < sizeof kMagic + 4 + 8)
        throw Error(fmt::format("{}: truncated checkpoint", path));
    Fnv1a hash;
    hash.add(bytes.data(), bytes.size() - 8);
    uint64_t stored_hash;
    std::memcpy(&stored_hash, bytes.data() + bytes.size() - 8, 8);
    if (hash.value != stored_hash)
        throw Error(
            fmt::format("{}: truncated or corrupt checkpoint (its checksum does not match)", path));

    const std::vector<std::string> differ = differences(get_identity(in), expected);
    if (!differ.empty()) {
        std::string list;
        for (const std::string& d : differ) list += "\n  " + d;
        throw Error(fmt::format(
            "{}: the checkpoint was made for another render; it has{}\nRender afresh without "
            "--resume (the checkpoint is then replaced), or resume with the settings above.",
            path, list));
    }
    RenderResult state = std::move(blank);
    state.passes = int(in.get<uint32_t>());
    state.seconds = in.get<double>(), state.rays = in.get<uint64_t>(),
    state.photons = in.get<uint64_t>();
    state.photon_radius = in.get<double>();
    state.photon_bytes = size_t(in.get<uint64_t>()),
    state.visible_point_bytes = size_t(in.get<uint64_t>());
    in.get_grids(state.film, state.receivers, "");
    const uint32_t layers = in.get<uint32_t>();
    if (layers != state.layers.size())
        in.fail(fmt::format("{} light layers in the checkpoint, {} in this render", layers,
                            state.layers.size()));
    for (RenderLayer& layer : state.layers) {
        const std::string name = in.get_string();
        if (name != layer.name)
            in.fail(fmt::format("layer '{}' where this render has '{}'", name, layer.name));
        in.get_grids(layer.film, layer.receivers, "layer " + name + " ");
    }
    in.get<uint64_t>();  // the checksum
    if (!in.at_end()) in.fail("bytes after the end of the checkpoint");
    if (state.passes < 1) in.fail("no completed pass");
    return state;
}

}  // namespace rayset::tracer
