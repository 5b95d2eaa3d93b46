#include "lightmodel/vdb_file.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/DelayedLoadMetadata.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/io/io.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <mutex>

namespace rayset::lightmodel {

namespace {

// What is wrong with a file, said without its name (read_vdb_file adds it).
struct Corrupt : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// More grids than any model has; a count above it is a corrupt file, not a model.
constexpr int32_t kMostGrids = 64;

// OpenVDB allocates a string or a metadata value of the length the file states before it reads
// it, so that a corrupt length asks for up to 4 GB. A scan walks the same structures first, from
// the stream's position, refuses a length beyond the end of the file and goes back.
class LengthScan {
public:
    LengthScan(std::istream& in, std::streamoff file_size)
        : in_(in), start_(in.tellg()), file_size_(file_size) {}

    LengthScan& skip(std::streamoff bytes) {
        check(bytes, in_.tellg());
        in_.seekg(bytes, std::ios::cur);
        return *this;
    }
    LengthScan& strings(int count) {
        for (int i = 0; i < count; ++i) skip(length());
        return *this;
    }
    // A MetaMap: a count, then name, type name and sized value of each item. Of the types
    // OpenVDB knows, only texts and the fixed-size types OpenVDB and the model write are taken,
    // at their own sizes: OpenVDB reads those at their size whatever the file states, and
    // others by counts of their own. Types it does not know it skips by the stated size.
    LengthScan& metadata() {
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
        LengthScan(in, file_size).metadata().back();
        file.meta->readMeta(in);
        check_metadata(*file.meta);
        const int32_t count = readGridCount(in);
        if (count < 0 || count > kMostGrids)
            throw Corrupt("the file claims " + std::to_string(count) + " grids (at most " +
                          std::to_string(kMostGrids) + ")");
        file.grids = std::make_shared<openvdb::GridPtrVec>();
        for (int32_t i = 0; i < count; ++i) {
            openvdb::io::GridDescriptor descriptor;
            LengthScan(in, file_size).strings(3).back();  // name, type, instance parent
            openvdb::GridBase::Ptr grid = descriptor.read(in);
            check_grid(descriptor, accepted);
            check_compression(in, descriptor);
            // The compression flags, the grid's metadata, its transform's type name.
            LengthScan(in, file_size).skip(4).metadata().strings(1).back();
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
    }

    // Peeks at the flags Archive::readGrid reads first.
    static void check_compression(std::istream& in, const openvdb::io::GridDescriptor& descriptor) {
        const std::streampos start = in.tellg();
        uint32_t flags = 0;
        in.read(reinterpret_cast<char*>(&flags), sizeof flags);
        in.seekg(start);
        if (flags & (openvdb::io::COMPRESS_ZIP | openvdb::io::COMPRESS_BLOSC))
            throw Corrupt(
                "grid '" + openvdb::io::GridDescriptor::nameAsString(descriptor.uniqueName()) +
                "' is stored with " + openvdb::io::compressionToString(flags) +
                " compression, which this reader refuses (files from raymodel have none)");
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
