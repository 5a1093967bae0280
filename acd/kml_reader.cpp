#include "acd/kml_reader.h"

#include <expat.h>
#include <unzip.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <exception>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "acd/internal/skipped_geometries.h"
#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using Json = nlohmann::ordered_json;

// An element's name without its namespace prefix: "kml:Polygon" -> "Polygon".
std::string LocalName(const char* name) {
  const char* colon = std::strrchr(name, ':');
  return colon == nullptr ? name : colon + 1;
}

// The value of attribute `name`, "" if it has none.
std::string Attribute(const char** attributes, const char* name) {
  for (int k = 0; attributes[k] != nullptr; k += 2) {
    if (LocalName(attributes[k]) == name) return attributes[k + 1];
  }
  return "";
}

// XML's white space (its S production), not std::isspace()'s, which adds \v and \f.
bool IsSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

// Walks the document's elements (expat's callbacks) and collects what ReadKml() returns. A
// callback must not throw through expat's C frames: it records the first error and stops the
// parser, and Parse() throws it.
class KmlParser {
 public:
  KmlParser(const std::string& source, bool skip_non_areal)
      : source_(source), skip_non_areal_(skip_non_areal) {}

  std::vector<Polygon2d> Parse(const std::string& text, KmlExtras* extras) {
    const std::unique_ptr<XML_ParserStruct, decltype(&XML_ParserFree)> parser(
        XML_ParserCreate(nullptr), &XML_ParserFree);
    if (!parser) throw std::bad_alloc();
    parser_ = parser.get();
    XML_SetUserData(parser_, this);
    XML_SetElementHandler(
        parser_,
        [](void* self, const char* name, const char** attributes) {
          static_cast<KmlParser*>(self)->Guarded([&](KmlParser& p) { p.Start(name, attributes); });
        },
        [](void* self, const char* name) {
          static_cast<KmlParser*>(self)->Guarded([&](KmlParser& p) { p.End(name); });
        });
    XML_SetCharacterDataHandler(parser_, [](void* self, const char* data, int size) {
      auto* p = static_cast<KmlParser*>(self);
      if (p->capturing_) p->text_.append(data, static_cast<size_t>(size));
    });
    // In pieces: XML_Parse() takes an int length.
    constexpr size_t kPiece = size_t{1} << 24;
    size_t at = 0;
    do {
      const size_t size = std::min(kPiece, text.size() - at);
      const bool last = at + size == text.size();
      if (XML_Parse(parser_, text.data() + at, static_cast<int>(size), last) != XML_STATUS_OK) {
        if (error_) std::rethrow_exception(error_);
        Fail("malformed XML: " + std::string(XML_ErrorString(XML_GetErrorCode(parser_))));
      }
      at += size;
    } while (at < text.size());
    if (error_) std::rethrow_exception(error_);
    if (!skipped_.empty()) extras_.warnings.push_back(skipped_.Note(source_));
    if (unclosed_ > 0) {
      extras_.warnings.push_back(first_unclosed_ +
                                 ": a ring without its closing point, taken as it is (" +
                                 std::to_string(unclosed_) + " in the file)");
    }
    *extras = std::move(extras_);
    return std::move(polygons_);
  }

 private:
  template <typename F>
  void Guarded(F&& f) {
    if (error_) return;
    try {
      f(*this);
    } catch (...) {
      error_ = std::current_exception();
      XML_StopParser(parser_, XML_FALSE);
    }
  }

  std::string Here() const {
    return source_ + ":" + std::to_string(XML_GetCurrentLineNumber(parser_));
  }
  [[noreturn]] void Fail(const std::string& rule) const { throw InputError(Here() + ": " + rule); }

  void Capture() {
    capturing_ = true;
    text_.clear();
    text_line_ = Here();
  }

  void Start(const char* raw_name, const char** attributes) {
    const std::string name = LocalName(raw_name);
    const std::string parent = path_.empty() ? std::string() : path_.back();
    // Google Earth also opens a fragment whose root is a Document, Folder or Placemark.
    if (path_.empty() && name != "kml" && name != "Document" && name != "Folder" &&
        name != "Placemark") {
      Fail("not KML: the root element is <" + std::string(raw_name) + ">, not <kml>");
    }
    path_.push_back(name);
    const bool in_polygon = polygon_depth_ >= 0;
    if (name == "Placemark") {
      placemark_depth_ = static_cast<int>(path_.size());
      feature_ = features_++;
      properties_ = Json::object();
    } else if (name == "Polygon") {
      if (in_polygon) Fail("a Polygon inside a Polygon");
      polygon_depth_ = static_cast<int>(path_.size());
      polygon_ = Polygon2d{};
      polygon_start_ = Here();
      if (placemark_depth_ < 0) feature_ = features_++;  // A polygon of its own.
    } else if (name == "outerBoundaryIs" || name == "innerBoundaryIs") {
      outer_ = name == "outerBoundaryIs";
    } else if (name == "coordinates") {
      Capture();
    } else if ((name == "LinearRing" && !in_polygon) || name == "Point" || name == "LineString" ||
               name == "Model" || name == "Track" || name == "MultiTrack") {
      if (!skip_non_areal_) Fail("a " + name + " has no area (only polygons are read here)");
      skipped_.Add(name, "line " + std::to_string(XML_GetCurrentLineNumber(parser_)));
    } else if (placemark_depth_ >= 0 && !in_polygon) {
      const bool attribute = ((name == "name" || name == "description") && parent == "Placemark") ||
                             (name == "value" && parent == "Data") || name == "SimpleData";
      if (name == "Data" || name == "SimpleData") data_name_ = Attribute(attributes, "name");
      if (name == "name" || name == "description") data_name_ = name;
      if (attribute) Capture();
    }
  }

  void End(const char* raw_name) {
    const std::string name = LocalName(raw_name);
    const bool captured = capturing_;
    capturing_ = false;
    if (name == "coordinates" && polygon_depth_ >= 0 && path_.size() >= 2 &&
        path_[path_.size() - 2] == "LinearRing") {
      Ring2d ring = Coordinates(text_);
      if (outer_) {
        if (!polygon_.outer.empty()) Fail("a Polygon with two outer boundaries");
        polygon_.outer = std::move(ring);
      } else if (!ring.empty()) {
        polygon_.holes.push_back(std::move(ring));
      }
    } else if (name == "Polygon") {
      polygon_depth_ = -1;
      if (polygon_.outer.empty() && !polygon_.holes.empty()) {
        throw InputError(polygon_start_ + ": a Polygon with inner boundaries but no outer one");
      }
      if (!polygon_.outer.empty()) {
        polygons_.push_back(std::move(polygon_));
        extras_.features.push_back(feature_);
      }
      if (placemark_depth_ < 0) extras_.properties.push_back("{}");
    } else if (name == "Placemark") {
      placemark_depth_ = -1;
      extras_.properties.push_back(
          properties_.dump(-1, ' ', false, Json::error_handler_t::replace));
    } else if (captured && name != "coordinates") {
      properties_[data_name_] = text_;
    }
    path_.pop_back();
  }

  // The tuples of a <coordinates> element (captured from text_line_).
  Ring2d Coordinates(const std::string& text) {
    // Tuples are separated by white space; white space beside a comma is within a tuple.
    std::string tidy;
    bool space = false;
    for (const char c : text) {
      if (IsSpace(c)) {
        space = true;
      } else {
        if (space && !tidy.empty() && c != ',' && tidy.back() != ',') tidy += ' ';
        tidy += c;
        space = false;
      }
    }
    Ring2d ring;
    size_t start = 0;
    while (start < tidy.size()) {
      size_t end = tidy.find(' ', start);
      if (end == std::string::npos) end = tidy.size();
      const std::string tuple = tidy.substr(start, end - start);
      double values[3];
      int count = 0;
      size_t from = 0;
      while (true) {
        const size_t comma = tuple.find(',', from);
        const std::string token = tuple.substr(from, comma - from);
        if (count == 3) {
          throw InputError(text_line_ + ": coordinates: tuple '" + tuple +
                           "' has more than 3 numbers (lon,lat[,alt])");
        }
        const internal::NumberStatus status = internal::ParseDouble(token, values[count]);
        if (status != internal::NumberStatus::kOk) {
          throw InputError(text_line_ + ": coordinates: " + internal::NumberProblem(status, token));
        }
        ++count;
        if (comma == std::string::npos) break;
        from = comma + 1;
      }
      if (count < 2) {
        throw InputError(text_line_ + ": coordinates: tuple '" + tuple +
                         "' has fewer than 2 numbers (lon,lat[,alt])");
      }
      ring.emplace_back(values[0], values[1]);
      start = end + 1;
    }
    if (ring.size() >= 2) {
      if (ring.front() == ring.back()) {
        ring.pop_back();
      } else if (unclosed_++ == 0) {
        first_unclosed_ = text_line_;
      }
    }
    return ring;
  }

  const std::string& source_;
  const bool skip_non_areal_;
  XML_Parser parser_ = nullptr;
  std::exception_ptr error_;  // The first error, from a callback.
  std::vector<std::string> path_;
  int features_ = 0, feature_ = -1;
  int placemark_depth_ = -1, polygon_depth_ = -1;
  Json properties_;
  std::string data_name_;
  Polygon2d polygon_;
  std::string polygon_start_;
  bool outer_ = true;
  bool capturing_ = false;
  std::string text_, text_line_;
  int unclosed_ = 0;
  std::string first_unclosed_;
  internal::SkippedGeometries skipped_;
  std::vector<Polygon2d> polygons_;
  KmlExtras extras_;
};

}  // namespace

std::vector<Polygon2d> ReadKml(std::istream& in, const std::string& source, bool skip_non_areal,
                               KmlExtras* extras) {
  const std::string text(std::istreambuf_iterator<char>(in), {});
  KmlExtras own;
  return KmlParser(source, skip_non_areal).Parse(text, extras != nullptr ? extras : &own);
}

std::string ReadKmzRoot(const std::string& path, std::string* entry) {
  OpenFile(path);  // The common message for a missing or unreadable file.
  const std::unique_ptr<void, decltype(&unzClose)> zip(unzOpen64(path.c_str()), &unzClose);
  if (!zip) throw InputError(path + ": not a KMZ (not a readable zip archive)");
  for (int status = unzGoToFirstFile(zip.get()); status == UNZ_OK;
       status = unzGoToNextFile(zip.get())) {
    unz_file_info64 info;
    char name[1024];
    if (unzGetCurrentFileInfo64(zip.get(), &info, name, sizeof name, nullptr, 0, nullptr, 0) !=
        UNZ_OK) {
      throw InputError(path + ": damaged zip archive (an entry's header)");
    }
    const std::string entry_name = name;
    if (entry_name.size() < 4 ||
        internal::ToLower(entry_name.substr(entry_name.size() - 4)) != ".kml") {
      continue;
    }
    const std::string where = path + "/" + entry_name;
    constexpr std::uint64_t kMaxBytes = std::uint64_t{1} << 30;
    if (info.uncompressed_size > kMaxBytes) {
      throw InputError(where + ": " + std::to_string(info.uncompressed_size) +
                       " bytes uncompressed, over the 1 GiB this reader takes");
    }
    if ((info.flag & 1) != 0) throw InputError(where + ": encrypted (not supported)");
    if (unzOpenCurrentFile(zip.get()) != UNZ_OK) {
      throw InputError(where +
                       ": cannot open the entry (damaged, or compressed by a method zlib "
                       "does not read)");
    }
    std::string text;
    char buffer[1 << 16];
    int read = 0;
    while ((read = unzReadCurrentFile(zip.get(), buffer, sizeof buffer)) > 0) {
      text.append(buffer, static_cast<size_t>(read));
      if (text.size() > kMaxBytes) throw InputError(where + ": over 1 GiB uncompressed");
    }
    // Closing checks the entry's CRC once it was read to the end.
    if (read < 0 || unzCloseCurrentFile(zip.get()) != UNZ_OK) {
      throw InputError(where + ": damaged entry (its data does not decompress or fails its CRC)");
    }
    if (entry != nullptr) *entry = entry_name;
    return text;
  }
  throw InputError(path + ": no .kml entry in the KMZ archive");
}

}  // namespace acdplan::acd
