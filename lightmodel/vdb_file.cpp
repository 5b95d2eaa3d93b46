#include "lightmodel/vdb_file.h"

#include "converters/rays/io.h"
#include "core/error.h"

#include <openvdb/io/Archive.h>
#include <openvdb/io/GridDescriptor.h>
#include <openvdb/io/io.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>

namespace rayset::lightmodel {

namespace {

// What is wrong with a file, said without its name (read_vdb_file adds it).
struct Corrupt : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// More grids than any model has; a count above it is a corrupt file, not a model.
constexpr int32_t kMostGrids = 64;

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

    VdbFile read_grids(std::istream& in, const VdbGridTypes& accepted,
                       const std::function<void(const openvdb::MetaMap&)>& check_metadata) {
        VdbFile file;
        file.meta = std::make_shared<openvdb::MetaMap>();
        file.meta->readMeta(in);
        check_metadata(*file.meta);
        const int32_t count = readGridCount(in);
        if (count < 0 || count > kMostGrids)
            throw Corrupt("the file claims " + std::to_string(count) + " grids (at most " +
                          std::to_string(kMostGrids) + ")");
        file.grids = std::make_shared<openvdb::GridPtrVec>();
        for (int32_t i = 0; i < count; ++i) {
            openvdb::io::GridDescriptor descriptor;
            openvdb::GridBase::Ptr grid = descriptor.read(in);
            check_grid(descriptor, accepted);
            check_compression(in, descriptor);
            readGrid(grid, descriptor, in);
            file.grids->push_back(grid);
        }
        return file;
    }

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

}  // namespace

VdbFile read_vdb_file(const std::string& path, const VdbGridTypes& accepted,
                      const std::function<void(const openvdb::MetaMap&)>& check_metadata) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(path + ": cannot open: " + std::strerror(errno));
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
        VdbFile file = archive.read_grids(in, accepted, check_metadata);
        openvdb::io::clearStreamMetadataPtr(in);
        return file;
    } catch (const std::ios_base::failure&) {
        throw Error(path + ": cannot read as an OpenVDB file: it ends early");
    } catch (const Error&) {
        throw;  // check_metadata's, which names the file
    } catch (const Corrupt& e) {
        throw Error(path + ": cannot read as an OpenVDB file: " + e.what());
    } catch (const std::exception& e) {
        // OpenVDB quotes what it read, such as a grid type of the length a corrupt file states
        // (128 MB): only the beginning of its message is kept.
        constexpr size_t kLongest = 300;
        std::string what = e.what();
        if (what.size() > kLongest) what = what.substr(0, kLongest) + "...";
        throw Error(path + ": cannot read as an OpenVDB file: " + what);
    }
}

// openvdb::io::File::write ignores a failing stream: on a full disk it leaves a truncated file
// and reports success. This writes the same archive (seekable, as File writes it) to a stream
// whose state is checked.
void write_vdb_file(const std::string& path, const openvdb::GridPtrVec& grids,
                    const openvdb::MetaMap& meta) {
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
