#include "envs/stl_reader.h"

#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "acd/internal/text_parsing.h"
#include "base/bit_hash.h"
#include "base/input_error.h"
#include "envs/internal/polygon_soup.h"
#include "envs/internal/text_words.h"

namespace acdplan::envs {
namespace {

using internal::PolygonSoup;

// STL repeats a corner in every facet around it: one vertex per position (exact; -0 and 0 are
// one position), numbered in order of first use.
class Corners {
 public:
  explicit Corners(PolygonSoup* soup) : soup_(soup) {}

  // The vertex at `p`; false if that would be one vertex more than an int counts.
  bool Add(const Eigen::Vector3d& p, int* vertex) {
    const Key key{p.x() + 0.0, p.y() + 0.0, p.z() + 0.0};  // -0 + 0 is +0.
    const auto [it, added] = index_.try_emplace(key, static_cast<int>(soup_->vertices.size()));
    if (added) {
      if (soup_->vertices.size() == static_cast<size_t>(INT_MAX)) return false;
      soup_->vertices.emplace_back(key[0], key[1], key[2]);
    }
    *vertex = it->second;
    return true;
  }

 private:
  using Key = std::array<double, 3>;
  struct Hash {
    size_t operator()(const Key& key) const {
      return static_cast<size_t>(BitHash(BitHash(BitHash(kBitHashSeed, key[0]), key[1]), key[2]));
    }
  };
  PolygonSoup* soup_;
  std::unordered_map<Key, int, Hash> index_;
};

constexpr size_t kBinaryHeader = 84;  // 80 bytes of anything, then the facet count.
constexpr size_t kBinaryFacet = 50;   // 12 floats and a 16-bit attribute word.

std::uint32_t LittleEndian32(const char* bytes) {
  std::uint32_t value = 0;
  for (int k = 3; k >= 0; --k) value = (value << 8) | static_cast<unsigned char>(bytes[k]);
  return value;
}

float LittleEndianFloat(const char* bytes) {
  const std::uint32_t bits = LittleEndian32(bytes);
  float value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

acd::TriangleMesh ReadBinary(const std::string& bytes, const std::string& source) {
  const std::uint64_t facets = LittleEndian32(bytes.data() + 80);
  const std::uint64_t needed = kBinaryHeader + kBinaryFacet * facets;
  if (bytes.size() != needed) {
    throw InputError(source + ": binary STL of " + std::to_string(facets) + " facets needs " +
                     std::to_string(needed) + " bytes, the file has " +
                     std::to_string(bytes.size()));
  }
  PolygonSoup soup;
  Corners corners(&soup);
  std::vector<int> face(3);
  for (std::uint64_t f = 0; f < facets; ++f) {
    const char* corner = bytes.data() + kBinaryHeader + kBinaryFacet * f + 12;  // After the normal.
    for (int k = 0; k < 3; ++k, corner += 12) {
      const Eigen::Vector3d p(LittleEndianFloat(corner), LittleEndianFloat(corner + 4),
                              LittleEndianFloat(corner + 8));
      if (!p.allFinite()) {
        throw InputError(source + ": facet " + std::to_string(f) + ": a corner is not finite");
      }
      if (!corners.Add(p, &face[k])) {
        throw InputError(source + ": more than " + std::to_string(INT_MAX) + " vertices");
      }
    }
    soup.AddFace(face);
  }
  return soup.Finish(source);
}

acd::TriangleMesh ReadAscii(std::string text, const std::string& source) {
  internal::TextWords words(std::move(text), 1);
  auto fail = [&](const std::string& rule) {
    throw InputError(source + ":" + std::to_string(words.Line()) + ": " + rule);
  };
  // The next word, lower-cased where it is a keyword; `what` names the expected for the end.
  std::string_view word;
  auto next = [&](const char* what) {
    if (!words.Next(&word)) fail(std::string("the file ends where ") + what + " was expected");
  };
  auto expect = [&](const char* keyword) {
    next(keyword);
    if (acd::internal::ToLower(word) != keyword) {
      fail(std::string("expected '") + keyword + "', got '" + std::string(word) + "'");
    }
  };
  PolygonSoup soup;
  Corners corners(&soup);
  std::vector<int> face;
  expect("solid");
  words.SkipLine();  // The solid's name.
  for (;;) {
    next("'facet' or 'endsolid'");
    const std::string keyword = acd::internal::ToLower(word);
    if (keyword == "endsolid") {
      words.SkipLine();
      if (!words.Next(&word)) break;  // Another solid may follow.
      if (acd::internal::ToLower(word) != "solid") {
        fail("expected 'solid' or the end of the file, got '" + std::string(word) + "'");
      }
      words.SkipLine();
      continue;
    }
    if (keyword != "facet") fail("expected 'facet' or 'endsolid', got '" + std::string(word) + "'");
    expect("normal");
    for (int k = 0; k < 3; ++k) next("the facet's normal");  // Unused: the corners orient it.
    expect("outer");
    expect("loop");
    face.clear();
    for (;;) {
      next("'vertex' or 'endloop'");
      const std::string corner = acd::internal::ToLower(word);
      if (corner == "endloop") break;
      if (corner != "vertex")
        fail("expected 'vertex' or 'endloop', got '" + std::string(word) + "'");
      Eigen::Vector3d p;
      for (int k = 0; k < 3; ++k) {
        next("a coordinate");
        const acd::internal::NumberStatus status = acd::internal::ParseDouble(word, p[k]);
        if (status != acd::internal::NumberStatus::kOk) {
          fail(acd::internal::NumberProblem(status, word));
        }
      }
      face.emplace_back();
      if (!corners.Add(p, &face.back())) fail("more than " + std::to_string(INT_MAX) + " vertices");
    }
    if (face.size() < 3)
      fail("a facet needs at least 3 vertices, got " + std::to_string(face.size()));
    expect("endfacet");
    soup.AddFace(face);
  }
  return soup.Finish(source);
}

}  // namespace

acd::TriangleMesh ReadStl(std::istream& in, const std::string& source) {
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const bool sized_as_binary =
      bytes.size() >= kBinaryHeader &&
      bytes.size() ==
          kBinaryHeader + kBinaryFacet * std::uint64_t{LittleEndian32(bytes.data() + 80)};
  const size_t start = bytes.find_first_not_of(" \t\r\n");
  const bool says_solid =
      start != std::string::npos &&
      acd::internal::ToLower(std::string_view(bytes).substr(start, 5)) == "solid";
  // Text has no control characters but white space; a binary file's floats and count do (a
  // binary file whose count is wrong then gets the size error, not one about its text).
  const bool text = std::none_of(bytes.begin(), bytes.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 && c != '\t' && c != '\n' && c != '\r' &&
           c != '\f' && c != '\v';
  });
  if (says_solid && !sized_as_binary && text) return ReadAscii(std::move(bytes), source);
  if (bytes.size() < kBinaryHeader) {
    throw InputError(source + ": not an STL file: ASCII STL starts with 'solid', binary STL has " +
                     "84 bytes at least, this file " + std::to_string(bytes.size()));
  }
  return ReadBinary(bytes, source);
}

}  // namespace acdplan::envs
