#include "lightmodel/vdb_file.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/io/io.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>
#include <set>
#include <vector>

namespace rayset::lightmodel {

namespace {

// What is wrong with a file, said without its name (read_vdb_file adds it).
struct Corrupt : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// More grids than any model has; a count above it is a corrupt file, not a model.
constexpr int32_t kMostGrids = 64;

// OpenVDB allocates a string or a metadata value of the length the file states before it reads
// it, so that a corrupt length asks for up to 4 GB; and when a tree's topology ends early it
// leaks the node it was reading (RootNode adopts a child only once the child is read), and the
// first of two children at one origin (the second replaces it in the root's table). A scan walks
// the same structures first, from the stream's position, refuses a length or a node beyond the
// end of the file and a second child at an origin, and goes back.
class LayoutScan {
public:
    LayoutScan(std::istream& in, std::streamoff file_size)
        : in_(in), start_(in.tellg()), file_size_(file_size) {}

    LayoutScan& skip(std::streamoff bytes) {
        check(bytes, in_.tellg());
        in_.seekg(bytes, std::ios::cur);
        return *this;
    }
    LayoutScan& strings(int count) {
        for (int i = 0; i < count; ++i) skip(length());
        return *this;
    }
    // A MetaMap: a count, then name, type name and sized value of each item. Of the types
    // OpenVDB knows, only texts and the fixed-size types OpenVDB and the model write are taken,
    // at their own sizes: OpenVDB reads those at their size whatever the file states, and
    // others by counts of their own. Types it does not know it skips by the stated size.
    LayoutScan& metadata() {
        const uint32_t count = number();
        for (uint32_t i = 0; i < count; ++i) {
            strings(1);
            std::string type(length(), '\0');
            in_.read(type.data(), std::streamsize(type.size()));
            const std::streamoff at = in_.tellg();
            const uint32_t bytes = length();
            if (type != openvdb::StringMetadata::staticTypeName() &&
                openvdb::Metadata::isRegisteredType(type) && bytes != fixed_size(type))
                throw Corrupt("metadata of type '" + type + "' and " + std::to_string(bytes) +
                              " bytes at byte " + std::to_string(at) +
                              ", which this reader refuses");
            skip(bytes);
        }
        return *this;
    }
    // A tree's topology as Tree, RootNode, InternalNode and LeafNode read it (file version 222
    // and later, a 5-4-3 tree of values of `value_bytes`): buffer count, background, tiles, then
    // each child of the root (origin and node) down to the leaves' value masks.
    LayoutScan& tree(std::streamoff value_bytes, bool mask_compressed) {
        skip(sizeof(int32_t) + value_bytes);
        const uint32_t tiles = number(), children = number();
        skip(std::streamoff(tiles) * (3 * sizeof(int32_t) + value_bytes + sizeof(bool)));
        std::set<std::array<int32_t, 3>> origins;
        for (uint32_t i = 0; i < children; ++i) {
            const std::streamoff at = in_.tellg();
            check(3 * sizeof(int32_t), at);
            std::array<int32_t, 3> origin{};
            in_.read(reinterpret_cast<char*>(origin.data()), 3 * sizeof(int32_t));
            if (!origins.insert(origin).second)
                throw Corrupt("a tree names a second node at (" + std::to_string(origin[0]) + ", " +
                              std::to_string(origin[1]) + ", " + std::to_string(origin[2]) +
                              ") at byte " + std::to_string(at));
            internal_node(5, value_bytes, mask_compressed);
        }
        return *this;
    }
    void back() { in_.seekg(start_); }

private:
    // The size of a metadata type OpenVDB reads at a fixed size; 0 for any other.
    static uint32_t fixed_size(const std::string& type) {
        using namespace openvdb;
        for (const auto& [name, size] :
             {std::pair<std::string, uint32_t>{BoolMetadata::staticTypeName(), sizeof(bool)},
              {Int32Metadata::staticTypeName(), sizeof(int32_t)},
              {Int64Metadata::staticTypeName(), sizeof(int64_t)},
              {FloatMetadata::staticTypeName(), sizeof(float)},
              {DoubleMetadata::staticTypeName(), sizeof(double)},
              {Vec3IMetadata::staticTypeName(), sizeof(Vec3i)},
              {Vec3SMetadata::staticTypeName(), sizeof(Vec3s)},
              {Vec3DMetadata::staticTypeName(), sizeof(Vec3d)}})
            if (type == name) return size;
        return 0;
    }

    // An InternalNode of 2^(3 log2dim) values: child mask, value mask, values, children (a
    // LeafNode below log2dim 4 reads its value mask alone).
    void internal_node(int log2dim, std::streamoff value_bytes, bool mask_compressed) {
        const size_t size = size_t(1) << (3 * log2dim);
        const std::vector<uint64_t> child_mask = mask(size), value_mask = mask(size);
        node_values(size, ones(value_mask), value_bytes, mask_compressed);
        for (size_t n = ones(child_mask); n > 0; --n) {
            if (log2dim > 4)
                internal_node(log2dim - 1, value_bytes, mask_compressed);
            else
                skip(512 / 8);
        }
    }
    // io::readCompressedValues: a metadata byte, then inactive values and a selection mask as it
    // says, then the active values alone (mask compression) or all of them.
    void node_values(size_t size, size_t active, std::streamoff value_bytes, bool mask_compressed) {
        char metadata = 0;
        in_.read(&metadata, 1);
        using namespace openvdb::io;
        if (metadata == NO_MASK_AND_ONE_INACTIVE_VAL || metadata == MASK_AND_ONE_INACTIVE_VAL)
            skip(value_bytes);
        if (metadata == MASK_AND_TWO_INACTIVE_VALS) skip(2 * value_bytes);
        if (metadata == MASK_AND_NO_INACTIVE_VALS || metadata == MASK_AND_ONE_INACTIVE_VAL ||
            metadata == MASK_AND_TWO_INACTIVE_VALS)
            skip(std::streamoff(size / 8));
        const bool only_active = mask_compressed && metadata != NO_MASK_AND_ALL_VALS;
        skip(std::streamoff(only_active ? active : size) * value_bytes);
    }
    std::vector<uint64_t> mask(size_t bits) {
        std::vector<uint64_t> words(bits / 64);
        check(std::streamoff(bits / 8), in_.tellg());
        in_.read(reinterpret_cast<char*>(words.data()), std::streamsize(bits / 8));
        return words;
    }
    static size_t ones(const std::vector<uint64_t>& words) {
        size_t count = 0;
        for (uint64_t w : words) count += size_t(__builtin_popcountll(w));
        return count;
    }

    uint32_t number() {
        uint32_t value = 0;
        in_.read(reinterpret_cast<char*>(&value), sizeof value);
        return value;
    }
    uint32_t length() {
        const std::streamoff field = in_.tellg();
        const uint32_t bytes = number();
        check(bytes, field);
        return bytes;
    }
    // `bytes` from the current position on, as the item at `field` states.
    void check(std::streamoff bytes, std::streamoff field) {
        const std::streamoff left = file_size_ - in_.tellg();
        if (bytes > left)
            throw Corrupt("a length of " + std::to_string(bytes) + " bytes at byte " +
                          std::to_string(field) + ", where the file has " + std::to_string(left) +
                          " left");
    }

    std::istream& in_;
    std::streamoff start_, file_size_;
};

// Archive's reading steps are protected: this is io::Stream's reading (header, metadata, then
// each grid after its descriptor) with the checks of vdb_file.h before each grid's data.
class GuardedArchive : public openvdb::io::Archive {
public:
    // The layout the checks below rely on: the per-grid compression flags of file version 222
    // and later.
    void read_header(std::istream& in) {
        readHeader(in);
        if (fileVersion() < openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION ||
            fileVersion() > openvdb::OPENVDB_FILE_VERSION)
            throw Corrupt("OpenVDB file format " + std::to_string(fileVersion()) +
                          ", where this reader takes " +
                          std::to_string(openvdb::OPENVDB_FILE_VERSION_NODE_MASK_COMPRESSION) +
                          " to " + std::to_string(openvdb::OPENVDB_FILE_VERSION));
    }

    VdbFile read_grids(std::istream& in, std::streamoff file_size, const VdbGridTypes& accepted,
                       const std::function<void(const openvdb::MetaMap&)>& check_metadata) {
        VdbFile file;
        file.meta = std::make_shared<openvdb::MetaMap>();
        LayoutScan(in, file_size).metadata().back();
        file.meta->readMeta(in);
        check_metadata(*file.meta);
        const int32_t count = readGridCount(in);
        if (count < 0 || count > kMostGrids)
            throw Corrupt("the file claims " + std::to_string(count) + " grids (at most " +
                          std::to_string(kMostGrids) + ")");
        file.grids = std::make_shared<openvdb::GridPtrVec>();
        for (int32_t i = 0; i < count; ++i) {
            openvdb::io::GridDescriptor descriptor;
            LayoutScan(in, file_size).strings(3).back();  // name, type, instance parent
            openvdb::GridBase::Ptr grid = descriptor.read(in);
            check_grid(descriptor, accepted);
            check_layout(in, file_size, descriptor, *grid);
            readGrid(grid, descriptor, in);
            file.grids->push_back(grid);
        }
        return file;
    }

    // Seekable, as io::File writes, so that OpenVDB's tools open it as they open their own.
    void write_seekable(std::ostream& out, const openvdb::GridPtrVec& grids,
                        const openvdb::MetaMap& meta) const {
        write(out, openvdb::GridCPtrVec(grids.begin(), grids.end()), true, meta);
    }

private:
    static void check_grid(const openvdb::io::GridDescriptor& descriptor,
                           const VdbGridTypes& accepted) {
        const std::string name = openvdb::io::GridDescriptor::nameAsString(descriptor.uniqueName());
        if (std::find(accepted.begin(), accepted.end(), descriptor.gridType()) == accepted.end())
            throw Corrupt("grid '" + name + "' is of type " + descriptor.gridType() +
                          ", which this file cannot hold");
        if (descriptor.isInstance())
            throw Corrupt("grid '" + name + "' shares the tree of another grid (instancing)");
        if (descriptor.saveFloatAsHalf())
            throw Corrupt("grid '" + name + "' is stored in half precision");
    }

    // What Archive::readGrid reads, walked before it reads it: the compression flags (zip and
    // blosc refused: OpenVDB reads their chunks by the lengths they state), the metadata, the
    // transform's type name, then (after the transform, read into a scratch grid to find its
    // end) the topology.
    static void check_layout(std::istream& in, std::streamoff file_size,
                             const openvdb::io::GridDescriptor& descriptor,
                             const openvdb::GridBase& grid) {
        const std::streampos start = in.tellg();
        LayoutScan(in, file_size).skip(sizeof(uint32_t)).metadata().strings(1).back();
        uint32_t flags = 0;
        in.read(reinterpret_cast<char*>(&flags), sizeof flags);
        if (flags & (openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_BLOSC))
            throw Corrupt(
                "grid '" + openvdb::io::GridDescriptor::nameAsString(descriptor.uniqueName()) +
                "' is stored with " + openvdb::io::compressionToString(flags) +
                " compression, which this reader refuses (files from raymodel have none)");
        openvdb::GridBase::Ptr scratch = grid.copyGridWithNewTree();
        scratch->readMeta(in);
        scratch->readTransform(in);
        LayoutScan(in, file_size)
            .tree(value_bytes(grid), flags & openvdb::io::COMPRESS_ACTIVE_MASK);
        in.seekg(start);
    }

    static std::streamoff value_bytes(const openvdb::GridBase& grid) {
        using Walked = openvdb::TypeList<openvdb::FloatGrid, openvdb::DoubleGrid,
                                         openvdb::Int32Grid, openvdb::Int64Grid>;
        std::streamoff bytes = 0;
        grid.apply<Walked>([&](const auto& typed) {
            bytes = sizeof(typename std::decay_t<decltype(typed)>::ValueType);
        });
        if (bytes == 0)
            throw Corrupt("grid type " + grid.type() + " is not one this reader can walk");
        return bytes;
    }
};

// OpenVDB's types registered, but not its delayed-load metadata, which every grid io::Archive
// writes carries (its leaf masks and sizes, blosc-compressed): OpenVDB reads it by the counts
// and blosc headers it holds, unchecked, and a whole read does not use it. Unregistered, it is
// unknown metadata, skipped by its stated size.
void prepare_openvdb() {
    static std::once_flag once;
    std::call_once(once, [] {
        openvdb::initialize();
        openvdb::Metadata::unregisterType(openvdb::io::DelayedLoadMetadata::staticTypeName());
    });
}

}  // namespace

VdbFile read_vdb_file(const std::string& path, const VdbGridTypes& accepted,
                      const std::function<void(const openvdb::MetaMap&)>& check_metadata) {
    prepare_openvdb();
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
    const std::streamoff file_size = in.tellg();
    in.seekg(0);
    // Every read past the end throws, so that no count in a corrupt file makes OpenVDB loop on.
    in.exceptions(std::ios::failbit | std::ios::badbit | std::ios::eofbit);
    try {
        GuardedArchive archive;
        archive.read_header(in);
        // The stream's tags, as io::Stream sets them; OpenVDB keeps a pointer to `stream_meta`.
        auto stream_meta = std::make_shared<openvdb::io::StreamMetadata>();
        openvdb::io::setStreamMetadataPtr(in, stream_meta, /*transfer=*/false);
        openvdb::io::setVersion(in, archive.libraryVersion(), archive.fileVersion());
        openvdb::io::setDataCompression(in, archive.compression());
        VdbFile file = archive.read_grids(in, file_size, accepted, check_metadata);
        openvdb::io::clearStreamMetadataPtr(in);
        return file;
    } catch (const std::ios_base::failure&) {
        throw Error(path +
                    ": cannot read as an OpenVDB file: it ends early or its structure is "
                    "corrupt");
    } catch (const Error&) {
        throw;  // check_metadata's, which names the file
    } catch (const Corrupt& e) {
        throw Error(path + ": cannot read as an OpenVDB file: " + e.what());
    } catch (const std::exception& e) {
        // OpenVDB quotes what it read, such as a grid type as long as the file: only the
        // beginning of its message is kept.
        constexpr size_t kLongest = 300;
        std::string what = e.what();
        if (what.size() > kLongest) what = what.substr(0, kLongest) + "...";
        throw Error(path + ": cannot read as an OpenVDB file: " + what);
    }
}

// openvdb::io::File::write ignores a failing stream: on a full disk it leaves a truncated file
// and reports success. This writes the same archive to a stream whose state is checked.
void write_vdb_file(const std::string& path, const openvdb::GridPtrVec& grids,
                    const openvdb::MetaMap& meta) {
    prepare_openvdb();
    write_atomically(path, [&](const std::string& temporary) {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        GuardedArchive archive;
        archive.setCompression(openvdb::io::COMPRESS_ACTIVE_MASK);
        archive.write_seekable(out, grids, meta);
        out.flush();
        if (!out) throw std::runtime_error(std::strerror(errno));
        return true;
    });
}

}  // namespace rayset::lightmodel
