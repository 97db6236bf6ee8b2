// The checkpoint file: an HDF5 file behind a 512-byte text header in HDF5's user block.
//
// The header (which HDF5 itself skips, so h5py and h5dump open the file as usual) reads
//   EDEM checkpoint
//   schema 1
//   version 0.1.0
//   bytes 123456
//   crc32 89abcdef
// `bytes` is the whole file's length and `crc32` (zlib's) covers everything after the header,
// so a truncated, extended or altered file is refused before HDF5 parses any of it. A file is
// written to a temporary name beside the target, flushed to disk, and renamed over it: a run
// killed while saving leaves the previous checkpoint as it was.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <functional>
#include <string>

#include "io/h5_archive.hpp"

namespace edem {

// The layout of what Model::save writes (model/checkpoint.cpp). Raise it with any change a
// reader of the old layout would misread; a file of a higher schema is refused.
// 2: bolt segments may be SegmentState::removed (cut where their rock was excavated).
inline constexpr int kCheckpointSchema = 2;
inline constexpr std::size_t kCheckpointHeaderBytes = 512;

struct CheckpointHeader {
  int schema = 0;
  std::string version;  // of the EDEM that wrote it
  std::uint64_t bytes = 0;
  std::uint32_t crc32 = 0;
};

// Writes `path` atomically: `fill` writes the HDF5 content into the open file (its root group).
// Throws edem::Error naming the file, leaving no temporary file and `path` untouched, on failure.
void write_checkpoint(const std::string& path, const std::function<void(hid_t file)>& fill);

// An open, verified checkpoint: its header and HDF5 file.
struct CheckpointFile {
  CheckpointHeader header;
  h5::Handle file;
};

// Opens `path` for reading after checking its header, length and checksum. Throws edem::Error
// saying what is wrong: missing, empty, not a checkpoint (an HDF5 file or something else),
// written by a newer schema, truncated or extended, or damaged.
CheckpointFile open_checkpoint(const std::string& path);

// The header alone, verified as open_checkpoint does (for a summary without reading the model).
CheckpointHeader read_checkpoint_header(const std::string& path);

}  // namespace edem
