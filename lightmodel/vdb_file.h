// OpenVDB files read as untrusted input and written so that a failure leaves nothing.
//
// Debian's OpenVDB 10.0 trusts what a file states: it reads a zip or blosc chunk of the stated
// length into a buffer of the length the grid needs before it compares the two, indexes a point
// attribute by a length other than the one it read, decompresses delayed-load metadata by its
// own counts, allocates every string and metadata value at the stated length before reading it,
// and leaks the node it was reading when a tree's topology ends early. So io::File is not used
// for reading. read_vdb_file reads the same archive, but first walks every length-prefixed item
// and every tree's topology and refuses a length or node beyond the end of the file; refuses a
// grid that is not a plain tree of the value types given (in full precision) or whose data are
// zip- or blosc-compressed; skips delayed-load metadata unread; and stops at the first read past
// the end of the file instead of letting OpenVDB's loops run on over a failed stream.
// write_vdb_file writes what it reads: plain trees without zip or blosc (active-value masks
// only).
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
// rayset::Error naming the file and what is wrong with it.
VdbFile read_vdb_file(const std::string& path, const VdbGridTypes& accepted,
                      const std::function<void(const openvdb::MetaMap&)>& check_metadata);

// Writes the grids and metadata through a temporary file renamed into place; throws
// rayset::Error naming the file when the write fails (a full disk among others).
void write_vdb_file(const std::string& path, const openvdb::GridPtrVec& grids,
                    const openvdb::MetaMap& meta);

}  // namespace rayset::lightmodel
