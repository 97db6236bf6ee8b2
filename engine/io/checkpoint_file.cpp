#include "io/checkpoint_file.hpp"

#include <fcntl.h>
#include <unistd.h>
#include <zlib.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <vector>

#include "core/error.hpp"
#include "io/temp_file.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "EDEM checkpoint\n";
constexpr std::string_view kHdf5Signature = "\x89HDF\r\n\x1a\n";

// The header's lines before "crc32": the checksum covers them as well as the HDF5 content.
std::string header_body(const CheckpointHeader& h) {
  return fmt::format("{}schema {}\nversion {}\nbytes {}\n", kMagic, h.schema, h.version, h.bytes);
}

std::string header_text(const CheckpointHeader& h) {
  return fmt::format("{}crc32 {:08x}\n", header_body(h), h.crc32);
}

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// zlib's CRC-32 of `prefix` followed by the bytes of `file` from `offset` to its end.
std::uint32_t checksum(std::FILE* file, std::string_view prefix, long offset) {
  uLong crc = crc32(0L, Z_NULL, 0);
  crc = crc32(crc, reinterpret_cast<const Bytef*>(prefix.data()), static_cast<uInt>(prefix.size()));
  std::fseek(file, offset, SEEK_SET);
  std::vector<unsigned char> buffer(1 << 20);
  for (;;) {
    const size_t n = std::fread(buffer.data(), 1, buffer.size(), file);
    if (n == 0) break;
    crc = crc32(crc, buffer.data(), static_cast<uInt>(n));
  }
  return static_cast<std::uint32_t>(crc);
}

void sync_directory(const fs::path& file) {
  const fs::path dir = file.parent_path().empty() ? fs::path(".") : file.parent_path();
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;  // the rename is done; only its durability across a power cut is weaker
  ::fsync(fd);
  ::close(fd);
}

// Reads and checks the header of `path` against the file's length and checksum.
CheckpointHeader verified_header(const std::string& path) {
  std::error_code ec;
  if (!fs::exists(path, ec)) fail("cannot read checkpoint '{}': no such file", path);
  if (fs::is_directory(path, ec)) fail("cannot read checkpoint '{}': it is a directory", path);
  if (!fs::is_regular_file(path, ec))  // a pipe would hang the reader, a device feed it forever
    fail("cannot read checkpoint '{}': it is not a regular file (a pipe, socket or device)", path);
  FilePtr file(std::fopen(path.c_str(), "rb"));
  if (!file) fail("cannot read checkpoint '{}': {}", path, std::strerror(errno));
  std::fseek(file.get(), 0, SEEK_END);
  const long size = std::ftell(file.get());
  if (size == 0) fail("'{}' is empty, not a checkpoint", path);
  std::string head(kCheckpointHeaderBytes, '\0');
  std::fseek(file.get(), 0, SEEK_SET);
  head.resize(std::fread(head.data(), 1, head.size(), file.get()));
  if (!head.starts_with(kMagic)) {
    if (head.starts_with(kHdf5Signature))
      fail("'{}' is an HDF5 file but not an EDEM checkpoint (it has no EDEM header)", path);
    fail("'{}' is not an EDEM checkpoint (it does not start with \"EDEM checkpoint\")", path);
  }
  if (head.size() < kCheckpointHeaderBytes)
    fail("'{}' is truncated: {} bytes, less than its {}-byte header", path, size, kCheckpointHeaderBytes);

  CheckpointHeader h;
  std::istringstream lines(head.substr(kMagic.size()));
  std::string key_schema, key_version, key_bytes, key_crc, crc_hex;
  lines >> key_schema >> h.schema >> key_version >> h.version >> key_bytes >> h.bytes >> key_crc >> crc_hex;
  const auto damaged_header = [&] { fail("'{}' is damaged: its header is unreadable", path); };
  if (!lines || key_schema != "schema" || key_version != "version" || key_bytes != "bytes" || key_crc != "crc32" ||
      crc_hex.size() != 8)
    damaged_header();
  char* end = nullptr;
  h.crc32 = static_cast<std::uint32_t>(std::strtoul(crc_hex.c_str(), &end, 16));
  if (end != crc_hex.c_str() + 8) damaged_header();
  const std::string text = header_text(h);
  if (head.compare(0, text.size(), text) != 0 || head.find_first_not_of('\0', text.size()) != std::string::npos)
    damaged_header();
  if (h.schema > kCheckpointSchema)
    fail("'{}' was written by a newer EDEM ({}, checkpoint schema {}); this EDEM ({}) reads schema {} and older",
         path, h.version, h.schema, EDEM_VERSION, kCheckpointSchema);
  if (h.schema < 1) damaged_header();
  if (static_cast<std::uint64_t>(size) < h.bytes)
    fail("'{}' is truncated: {} of its {} bytes are there", path, size, h.bytes);
  if (static_cast<std::uint64_t>(size) > h.bytes)
    fail("'{}' is damaged: {} bytes where {} were written", path, size, h.bytes);
  if (checksum(file.get(), header_body(h), static_cast<long>(kCheckpointHeaderBytes)) != h.crc32)
    fail("'{}' is damaged: its content does not match the checksum it was written with", path);
  return h;
}

}  // namespace

void write_checkpoint(const std::string& path, const std::function<void(hid_t file)>& fill) {
  std::error_code ec;
  const fs::path target(path);
  if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ec))
    fail("cannot write '{}': directory '{}' does not exist", path, target.parent_path().string());
  if (fs::is_directory(target, ec)) fail("cannot write '{}': it is a directory", path);
  remove_stale_temporaries(target);  // a killed save's (a checkpoint's can be tens of MB)
  TempFile tmp(target);
  {
    const h5::QuietErrors quiet;
    const h5::Handle plist(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    H5Pset_userblock(plist.get(), kCheckpointHeaderBytes);
    h5::Handle file(H5Fcreate(tmp.path().c_str(), H5F_ACC_TRUNC, plist.get(), H5P_DEFAULT), H5Fclose);
    if (file.get() < 0) fail("cannot write '{}': HDF5 could not create '{}'", path, tmp.path().string());
    fill(file.get());
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot write '{}': HDF5 could not flush it", path);
  }
  FilePtr file(std::fopen(tmp.path().c_str(), "r+b"));
  if (!file) fail("cannot write '{}': {}", path, std::strerror(errno));
  std::fseek(file.get(), 0, SEEK_END);
  CheckpointHeader h;
  h.schema = kCheckpointSchema;
  h.version = EDEM_VERSION;
  h.bytes = static_cast<std::uint64_t>(std::ftell(file.get()));
  h.crc32 = checksum(file.get(), header_body(h), static_cast<long>(kCheckpointHeaderBytes));
  std::string text = header_text(h);
  text.resize(kCheckpointHeaderBytes, '\0');
  std::fseek(file.get(), 0, SEEK_SET);
  if (std::fwrite(text.data(), 1, text.size(), file.get()) != text.size() || std::fflush(file.get()) != 0 ||
      ::fsync(fileno(file.get())) != 0)
    fail("cannot write '{}': {}", path, std::strerror(errno));
  file.reset();
  tmp.move_into_place();
  sync_directory(target);
}

CheckpointHeader read_checkpoint_header(const std::string& path) { return verified_header(path); }

CheckpointFile open_checkpoint(const std::string& path) {
  CheckpointFile out;
  out.header = verified_header(path);
  const h5::QuietErrors quiet;
  out.file = h5::Handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (out.file.get() < 0) fail("'{}' is damaged: HDF5 cannot open it", path);
  return out;
}

}  // namespace edem
