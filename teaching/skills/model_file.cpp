#include "teaching/skills/model_file.hpp"

#include <cstring>
#include <system_error>

#include "engine/core/atomic_file.hpp"
#include "engine/core/error.hpp"
#include "engine/core/input_file.hpp"

namespace sc {

namespace {

constexpr char kMagic[8] = {'S', 'C', 'M', 'O', 'D', 'E', 'L', '\0'};
constexpr std::uint32_t kMaxNameLength = 256;
constexpr std::uint32_t kMaxRank = 4;
constexpr std::int64_t kMaxElements = std::int64_t{1} << 28;
constexpr std::uintmax_t kMaxModelFileBytes = std::uintmax_t{1} << 31;  // kMaxElements floats and then some

std::uint64_t fnv1a(const char* data, std::size_t size) {
  std::uint64_t h = 1469598103934665603ull;
  for (std::size_t i = 0; i < size; ++i) {
    h ^= static_cast<unsigned char>(data[i]);
    h *= 1099511628211ull;
  }
  return h;
}

template <typename T>
void put(std::string& out, T value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  out.append(bytes, sizeof(T));
}

// Sequential reader that turns every overrun into a one-line InputError.
class Reader {
 public:
  Reader(const std::string& bytes, std::size_t end, std::string file)
      : bytes_(bytes), end_(end), file_(std::move(file)) {}
  template <typename T>
  T get(const char* what) {
    T value;
    need(sizeof(T), what);
    std::memcpy(&value, bytes_.data() + pos_, sizeof(T));
    pos_ += sizeof(T);
    return value;
  }
  std::string text(std::size_t n, const char* what) {
    need(n, what);
    std::string s = bytes_.substr(pos_, n);
    pos_ += n;
    return s;
  }
  void floats(std::vector<float>& out, std::size_t n, const std::string& what) {
    need(n * sizeof(float), what.c_str());
    out.resize(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + pos_, n * sizeof(float));
    pos_ += n * sizeof(float);
  }
  bool at_end() const { return pos_ == end_; }
  [[noreturn]] void fail(const std::string& problem) const { throw InputError(file_, problem); }

 private:
  void need(std::size_t n, const char* what) const {
    if (end_ - pos_ < n) fail(std::string("corrupt model file: ends inside ") + what);
  }
  const std::string& bytes_;
  std::size_t end_;
  std::size_t pos_ = 0;
  std::string file_;
};

}  // namespace

void write_model_file(const std::filesystem::path& file, const ModelFileContents& contents) {
  std::string out(kMagic, sizeof(kMagic));
  put<std::uint32_t>(out, kModelFormatVersion);
  const std::string header = contents.header.dump();
  put<std::uint32_t>(out, static_cast<std::uint32_t>(header.size()));
  out += header;
  put<std::uint32_t>(out, static_cast<std::uint32_t>(contents.tensors.size()));
  for (const auto& t : contents.tensors) {
    put<std::uint32_t>(out, static_cast<std::uint32_t>(t.name.size()));
    out += t.name;
    put<std::uint32_t>(out, static_cast<std::uint32_t>(t.shape.size()));
    for (auto d : t.shape) put<std::int64_t>(out, d);
    out.append(reinterpret_cast<const char*>(t.values.data()), t.values.size() * sizeof(float));
  }
  put<std::uint64_t>(out, fnv1a(out.data(), out.size()));

  write_file_atomically(file, out);
}

ModelFileContents read_model_file(const std::filesystem::path& file) {
  const std::string name = file.string();
  std::error_code ec;  // the non-throwing form: a directory we may not search is not an exception
  if (!std::filesystem::exists(file, ec) && !ec) throw InputError(name, "no such model file");
  const std::string bytes = read_input_file(file, kMaxModelFileBytes);

  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw InputError(name, "not a SkillCoach model file (wrong magic bytes)");
  const std::size_t minimum = sizeof(kMagic) + 4 + 4 + 4 + 8;
  if (bytes.size() < minimum)
    throw InputError(name, "truncated model file (" + std::to_string(bytes.size()) + " bytes)");
  std::uint32_t version;
  std::memcpy(&version, bytes.data() + sizeof(kMagic), sizeof(version));
  if (version > kModelFormatVersion)
    throw InputError(name, "model format version " + std::to_string(version) +
                               " is newer than this program supports (" + std::to_string(kModelFormatVersion) +
                               "); update SkillCoach or retrain the model");
  if (version == 0) throw InputError(name, "corrupt model file: format version 0");
  const std::size_t body = bytes.size() - 8;
  std::uint64_t stored;
  std::memcpy(&stored, bytes.data() + body, sizeof(stored));
  if (stored != fnv1a(bytes.data(), body))
    throw InputError(name, "corrupt or truncated model file (checksum mismatch)");

  Reader r(bytes, body, name);
  r.text(sizeof(kMagic), "the magic bytes");
  r.get<std::uint32_t>("the version");
  ModelFileContents out;
  const auto header_length = r.get<std::uint32_t>("the header length");
  out.header = parse_json_text(r.text(header_length, "the header"), name + ": header");
  const auto count = r.get<std::uint32_t>("the tensor count");
  for (std::uint32_t i = 0; i < count; ++i) {
    NamedTensor t;
    const auto name_length = r.get<std::uint32_t>("a tensor name length");
    if (name_length > kMaxNameLength)
      r.fail("corrupt model file: tensor name of " + std::to_string(name_length) + " bytes");
    t.name = r.text(name_length, "a tensor name");
    const auto rank = r.get<std::uint32_t>("a tensor rank");
    if (rank > kMaxRank) r.fail("corrupt model file: tensor \"" + t.name + "\" has rank " + std::to_string(rank));
    std::int64_t elements = 1;
    for (std::uint32_t d = 0; d < rank; ++d) {
      const auto dim = r.get<std::int64_t>("a tensor shape");
      if (dim < 0 || dim > kMaxElements || elements * (dim == 0 ? 1 : dim) > kMaxElements)
        r.fail("corrupt model file: tensor \"" + t.name + "\" has an impossible shape");
      t.shape.push_back(dim);
      elements *= dim;
    }
    r.floats(t.values, static_cast<std::size_t>(elements), "tensor \"" + t.name + "\"");
    out.tensors.push_back(std::move(t));
  }
  if (!r.at_end()) r.fail("corrupt model file: unexpected bytes after the last tensor");
  return out;
}

}  // namespace sc
