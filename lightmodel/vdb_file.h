// OpenVDB files read as untrusted input and written so that a failure leaves nothing.
//
// Debian's OpenVDB 10.0 reads a zip or blosc chunk of the length the file states into a buffer of
// the length the grid needs before it compares the two, and reads a point attribute of one length
// and indexes it by another: a corrupt file overflows the heap. Its io::File is therefore not used
// for reading. read_vdb_file follows the same archive layout but refuses, before OpenVDB reads a
// grid's data, every grid that is not a plain tree of the value types given or whose data are zip-
// or blosc-compressed, and it stops at the first read past the end of the file instead of letting
// OpenVDB's loops go on over a failed stream. write_vdb_file writes only what it reads: plain
// trees, no zip or blosc (active-value masks only).
#pragma once

#include <openvdb/openvdb.h>

#include <functional>
#include <string>
#include <vector>

namespace rayset::lightmodel {

struct VdbFile {
    openvdb::GridPtrVecPtr grids;
    openvdb::MetaMap::Ptr meta;
};

// The grid types (GridBase::type(), e.g. openvdb::FloatGrid::gridType()) a file may hold.
using VdbGridTypes = std::vector<std::string>;

// Reads a whole file; `check_metadata` sees the file's metadata before any grid is read and
// throws rayset::Error to refuse the file (a model of another version, say). Throws
// rayset::Error naming the file and what is wrong with it. openvdb::initialize() must have run.
VdbFile read_vdb_file(const std::string& path, const VdbGridTypes& accepted,
                      const std::function<void(const openvdb::MetaMap&)>& check_metadata);

// Writes the grids and metadata through a temporary file renamed into place; throws
// rayset::Error naming the file when the write fails (a full disk among others).
void write_vdb_file(const std::string& path, const openvdb::GridPtrVec& grids,
                    const openvdb::MetaMap& meta);

}  // namespace rayset::lightmodel
