#include "io/bag_precheck.hpp"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "io/input_error.hpp"
#include "io/input_limits.hpp"

namespace shelfdock::io {
namespace {

constexpr char kMagic[] = "#ROSBAG V2.0\n";
constexpr std::uint64_t kMagicBytes = sizeof(kMagic) - 1;
constexpr std::uint32_t kMaxHeaderBytes = 1 << 16;  // headers hold a few short fields

enum Op : std::uint8_t {
  kMessageData = 0x02,
  kBagHeader = 0x03,
  kIndexData = 0x04,
  kChunk = 0x05,
  kChunkInfo = 0x06,
  kConnection = 0x07,
};

/// One record: its header fields and where its data lies.
struct Record {
  std::map<std::string, std::string> fields;
  std::uint64_t data_pos = 0;
  std::uint32_t data_len = 0;
  std::uint64_t end = 0;

  std::optional<std::uint8_t> op() const {
    const auto it = fields.find("op");
    if (it == fields.end() || it->second.size() != 1) return std::nullopt;
    return static_cast<std::uint8_t>(it->second[0]);
  }
  template <typename T>
  std::optional<T> Number(const std::string& name) const {
    const auto it = fields.find(name);
    if (it == fields.end() || it->second.size() != sizeof(T)) return std::nullopt;
    T value;
    std::memcpy(&value, it->second.data(), sizeof(T));
    return value;
  }
};

/// Reads record headers from the file (seeking over data): memory is one header whatever the
/// bag's length.
class BagWalker {
 public:
  BagWalker(const std::string& path, std::ifstream& in, std::uint64_t size)
      : path_(path), in_(in), size_(size) {}

  [[noreturn]] void Fail(std::uint64_t at, const std::string& what) const {
    throw InputError(path_, "byte " + std::to_string(at), "corrupt ROS bag: " + what);
  }

  std::string Bytes(std::uint64_t at, std::uint64_t n) const {
    std::string out(n, '\0');
    in_.clear();
    in_.seekg(static_cast<std::streamoff>(at));
    in_.read(out.data(), static_cast<std::streamsize>(n));
    if (static_cast<std::uint64_t>(in_.gcount()) != n) Fail(at, "cannot read");
    return out;
  }

  std::uint32_t U32(std::uint64_t at, std::uint64_t end) const {
    if (at + 4 > end) Fail(at, "record cut short");
    const std::string b = Bytes(at, 4);
    std::uint32_t v;
    std::memcpy(&v, b.data(), 4);  // little-endian, as on every ROS host
    return v;
  }

  /// The record at `at`, which must end by `end`.
  Record Read(std::uint64_t at, std::uint64_t end) const {
    Record r;
    const std::uint32_t header_len = U32(at, end);
    if (header_len > kMaxHeaderBytes || at + 4 + header_len > end) {
      Fail(at, "record header of " + std::to_string(header_len) + " bytes runs past its end");
    }
    const std::uint64_t header_end = at + 4 + header_len;
    const std::string header = Bytes(at + 4, header_len);
    for (std::uint64_t p = 0; p < header_len;) {
      if (p + 4 > header_len) Fail(at + 4 + p, "header field cut short");
      std::uint32_t field_len;
      std::memcpy(&field_len, header.data() + p, 4);
      if (p + 4 + field_len > header_len) Fail(at + 4 + p, "header field runs past its header");
      const std::string field = header.substr(p + 4, field_len);
      const auto eq = field.find('=');
      if (eq == std::string::npos) Fail(at + 4 + p, "header field without '='");
      r.fields[field.substr(0, eq)] = field.substr(eq + 1);
      p += 4 + field_len;
    }
    r.data_len = U32(header_end, end);
    r.data_pos = header_end + 4;
    if (r.data_pos + r.data_len > end) {
      Fail(at, "record data of " + std::to_string(r.data_len) + " bytes runs past its end");
    }
    r.end = r.data_pos + r.data_len;
    if (!r.op()) Fail(at, "record without an op field");
    return r;
  }

  /// Every record of a chunk stored uncompressed lies within the chunk.
  void CheckChunkContents(const Record& chunk) const {
    for (std::uint64_t p = chunk.data_pos; p < chunk.end;) p = Read(p, chunk.end).end;
  }

  void Walk() const {
    const std::uint64_t size = size_;
    if (size < kMagicBytes || Bytes(0, kMagicBytes) != kMagic) {
      Fail(0, "expected the ROS bag 2.0 magic line '#ROSBAG V2.0'");
    }
    std::set<std::uint64_t> starts, chunks;
    std::vector<std::uint64_t> chunk_refs;
    std::optional<std::uint64_t> index_pos;
    for (std::uint64_t p = kMagicBytes; p < size;) {
      const Record r = Read(p, size);
      starts.insert(p);
      switch (*r.op()) {
        case kBagHeader:
          index_pos = r.Number<std::uint64_t>("index_pos");
          if (!index_pos) Fail(p, "bag header without index_pos");
          break;
        case kChunk: {
          const auto chunk_size = r.Number<std::uint32_t>("size");
          const auto compression = r.fields.find("compression");
          if (!chunk_size || compression == r.fields.end()) Fail(p, "chunk without size");
          if (*chunk_size > kMaxBagChunkBytes) {
            Fail(p, "chunk of " + std::to_string(*chunk_size) + " bytes exceeds the limit of " +
                        std::to_string(kMaxBagChunkBytes));
          }
          if (compression->second == "none") {
            if (*chunk_size != r.data_len) Fail(p, "chunk size differs from its data");
            CheckChunkContents(r);
          }
          chunks.insert(p);
          break;
        }
        case kChunkInfo: {
          const auto chunk_pos = r.Number<std::uint64_t>("chunk_pos");
          if (!chunk_pos) Fail(p, "chunk info without chunk_pos");
          chunk_refs.push_back(*chunk_pos);
          break;
        }
        default:
          break;
      }
      p = r.end;
    }
    if (!index_pos) Fail(kMagicBytes, "no bag header record");
    if (*index_pos != 0 && *index_pos != size && starts.count(*index_pos) == 0) {
      Fail(kMagicBytes, "index_pos " + std::to_string(*index_pos) + " is not a record");
    }
    for (const std::uint64_t c : chunk_refs) {
      if (chunks.count(c) == 0) Fail(c, "chunk info points at no chunk");
    }
  }

 private:
  const std::string& path_;
  std::ifstream& in_;
  std::uint64_t size_;
};

}  // namespace

void PrecheckBag(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", "cannot open file");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw InputError(path, "", "cannot read file");
  BagWalker(path, in, static_cast<std::uint64_t>(size)).Walk();
}

}  // namespace shelfdock::io
