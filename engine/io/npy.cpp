#include "engine/io/npy.h"

#include <cstring>
#include <limits>

#include "engine/io/byte_view.h"
#include "engine/io/file_bytes.h"
#include "engine/io/float16.h"

namespace hdprior {
namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr size_t kMagicSize = 6;

struct Header {
  NpyDtype dtype;
  std::vector<size_t> shape;
  size_t dataOffset;
};

size_t dtypeSize(NpyDtype d) { return d == NpyDtype::Float16 ? 2 : d == NpyDtype::Float32 ? 4 : 8; }

const char* dtypeDescr(NpyDtype d) {
  return d == NpyDtype::Float16 ? "<f2" : d == NpyDtype::Float32 ? "<f4" : "<f8";
}

// The value of `key` in numpy's header dict: a quoted string, True/False, or a tuple.
std::string dictValue(const ByteView& view, const std::string& dict, const std::string& key) {
  size_t pos = dict.find("'" + key + "'");
  if (pos == std::string::npos) view.fail("npy header has no '" + key + "' entry");
  pos = dict.find_first_not_of(" :", pos + key.size() + 2);
  if (pos == std::string::npos) view.fail("npy header entry '" + key + "' has no value");
  const char open = dict[pos];
  const char close = open == '\'' ? '\'' : open == '(' ? ')' : '\0';
  const size_t end = close ? dict.find(close, pos + 1) : dict.find_first_of(",}", pos);
  if (end == std::string::npos) view.fail("npy header entry '" + key + "' is not terminated");
  return dict.substr(pos, end - pos + (close ? 1 : 0));
}

NpyDtype parseDescr(const ByteView& view, const std::string& descr) {
  if (descr == "'<f2'") return NpyDtype::Float16;
  if (descr == "'<f4'") return NpyDtype::Float32;
  if (descr == "'<f8'") return NpyDtype::Float64;
  view.fail("unsupported npy dtype " + descr + " (expected little-endian float16/32/64: '<f2', '<f4', '<f8')");
}

std::vector<size_t> parseShape(const ByteView& view, const std::string& tuple) {
  if (tuple.size() < 2 || tuple.front() != '(' || tuple.back() != ')') view.fail("malformed npy shape '" + tuple + "'");
  std::vector<size_t> shape;
  std::string digits;
  for (char c : tuple.substr(1, tuple.size() - 2) + ",") {
    if (c >= '0' && c <= '9') {
      digits += c;
    } else if (c == ',') {
      if (digits.empty()) continue;
      if (digits.size() > 12) view.fail("npy shape dimension " + digits + " is too large");
      shape.push_back(std::stoull(digits));
      digits.clear();
    } else if (c != ' ' && c != 'L') {
      view.fail("malformed npy shape " + tuple);
    }
  }
  return shape;
}

Header parseHeader(const ByteView& view) {
  view.require(0, kMagicSize + 2, "npy magic");
  if (std::memcmp(view.bytes().data(), kMagic, kMagicSize) != 0) view.fail("bad magic: not a .npy file");
  const uint8_t major = view.read<uint8_t>(6);
  size_t headerLen = 0, headerStart = 0;
  if (major == 1) {
    headerLen = view.read<uint16_t>(8, "npy header length");
    headerStart = 10;
  } else if (major == 2 || major == 3) {
    headerLen = view.read<uint32_t>(8, "npy header length");
    headerStart = 12;
  } else {
    view.fail("unsupported npy format version " + std::to_string(major));
  }
  if (headerLen > 65536) view.fail("npy header length " + std::to_string(headerLen) + " is implausibly large");
  view.require(headerStart, headerLen, "npy header");
  const std::string dict(reinterpret_cast<const char*>(view.bytes().data() + headerStart), headerLen);
  if (dict.find('{') == std::string::npos || dict.find('}') == std::string::npos) view.fail("malformed npy header");
  if (dictValue(view, dict, "fortran_order") != "False") view.fail("Fortran-order npy arrays are not supported");
  return Header{parseDescr(view, dictValue(view, dict, "descr")), parseShape(view, dictValue(view, dict, "shape")),
                headerStart + headerLen};
}

}  // namespace

NpyArray parseNpy(std::span<const uint8_t> bytes, const std::string& source) {
  const ByteView view(bytes, source);
  const Header h = parseHeader(view);
  size_t count = 1;
  for (size_t d : h.shape) {
    if (d != 0 && count > std::numeric_limits<size_t>::max() / d) view.fail("npy shape overflows");
    count *= d;
  }
  const size_t width = dtypeSize(h.dtype);
  if (count > (view.size() - h.dataOffset) / width) {
    view.fail("truncated: shape needs " + std::to_string(count * width) + " data bytes, file has " +
              std::to_string(view.size() - h.dataOffset));
  }
  if (count * width != view.size() - h.dataOffset) {
    view.fail("npy data is " + std::to_string(view.size() - h.dataOffset) + " bytes, shape needs " +
              std::to_string(count * width));
  }
  NpyArray a{h.dtype, h.shape, std::vector<float>(count)};
  const uint8_t* data = bytes.data() + h.dataOffset;
  for (size_t i = 0; i < count; ++i) {
    if (h.dtype == NpyDtype::Float16) {
      uint16_t v;
      std::memcpy(&v, data + 2 * i, 2);
      a.values[i] = halfToFloat(v);
    } else if (h.dtype == NpyDtype::Float32) {
      std::memcpy(&a.values[i], data + 4 * i, 4);
    } else {
      double v;
      std::memcpy(&v, data + 8 * i, 8);
      a.values[i] = static_cast<float>(v);
    }
  }
  return a;
}

NpyArray readNpy(const std::filesystem::path& path) { return parseNpy(readFileBytes(path), path.string()); }

std::vector<uint8_t> serializeNpy(const NpyArray& array) {
  std::string dict = std::string("{'descr': '") + dtypeDescr(array.dtype) + "', 'fortran_order': False, 'shape': (";
  for (size_t i = 0; i < array.shape.size(); ++i) dict += (i ? ", " : "") + std::to_string(array.shape[i]);
  if (array.shape.size() == 1) dict += ",";
  dict += "), }";
  // Pad so magic + version + length + header + '\n' is a multiple of 64 (as numpy does).
  const size_t unpadded = 10 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::vector<uint8_t> out(kMagic, kMagic + kMagicSize);
  out.push_back(1);
  out.push_back(0);
  const uint16_t len = static_cast<uint16_t>(dict.size());
  out.push_back(uint8_t(len & 0xff));
  out.push_back(uint8_t(len >> 8));
  out.insert(out.end(), dict.begin(), dict.end());
  const size_t width = dtypeSize(array.dtype);
  const size_t start = out.size();
  out.resize(start + array.values.size() * width);
  for (size_t i = 0; i < array.values.size(); ++i) {
    uint8_t* dst = out.data() + start + i * width;
    if (array.dtype == NpyDtype::Float16) {
      const uint16_t h = floatToHalf(array.values[i]);
      std::memcpy(dst, &h, 2);
    } else if (array.dtype == NpyDtype::Float32) {
      std::memcpy(dst, &array.values[i], 4);
    } else {
      const double d = array.values[i];
      std::memcpy(dst, &d, 8);
    }
  }
  return out;
}

void writeNpy(const std::filesystem::path& path, const NpyArray& array) {
  writeFileAtomically(path, serializeNpy(array));
}

}  // namespace hdprior
