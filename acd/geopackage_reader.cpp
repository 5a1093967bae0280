#include "acd/geopackage_reader.h"

#include <sqlite3.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <new>
#include <nlohmann/json.hpp>

#include "acd/internal/skipped_geometries.h"
#include "acd/internal/text_parsing.h"
#include "acd/wkb_reader.h"
#include "base/file_io.h"
#include "base/input_error.h"

namespace acdplan::acd {
namespace {

using Database = std::unique_ptr<sqlite3, decltype(&sqlite3_close)>;

// "name" as an SQL identifier.
std::string Quoted(const std::string& name) {
  std::string quoted = "\"";
  for (const char c : name) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// One prepared statement; a failure is the file's fault, so an InputError naming it.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& source) : source_(source) {
    if (sqlite3_prepare_v2(db, sql.c_str(), -1, &statement_, nullptr) != SQLITE_OK) {
      Fail(db);
    }
  }
  ~Statement() { sqlite3_finalize(statement_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  // Advances to the next row; false when there is none.
  bool Step() {
    const int status = sqlite3_step(statement_);
    if (status == SQLITE_ROW) return true;
    if (status != SQLITE_DONE) Fail(sqlite3_db_handle(statement_));
    return false;
  }
  sqlite3_stmt* get() const { return statement_; }
  std::string Text(int column) const {
    const unsigned char* text = sqlite3_column_text(statement_, column);
    return text == nullptr ? std::string() : reinterpret_cast<const char*>(text);
  }

 private:
  [[noreturn]] void Fail(sqlite3* db) const {
    throw InputError(source_ + ": not a readable GeoPackage: " + sqlite3_errmsg(db));
  }
  sqlite3_stmt* statement_ = nullptr;
  const std::string& source_;
};

// A feature layer as gpkg_contents and gpkg_geometry_columns list it.
struct Layer {
  std::string table, geometry_column, geometry_type;
  long long srs_id = 0;
};

// Whether a layer of that declared geometry type can hold polygons (OGC 12-128r18 Annex E and
// the non-linear geometry types extension).
bool MayHoldPolygons(const std::string& geometry_type) {
  static const char* const kAreal[] = {"polygon",           "multipolygon", "curvepolygon",
                                       "multisurface",      "surface",      "geometry",
                                       "geometrycollection"};
  const std::string lower = internal::ToLower(geometry_type);
  for (const char* type : kAreal) {
    if (lower == type) return true;
  }
  return false;
}

std::string LayerList(const std::vector<Layer>& layers) {
  std::vector<std::string> names;
  for (const Layer& layer : layers) names.push_back(layer.table);
  return JoinNames(names);
}

Layer ChooseLayer(sqlite3* db, const std::string& source, const std::string& wanted) {
  {
    Statement check(db,
                    "SELECT count(*) FROM sqlite_master WHERE type IN ('table', 'view') AND "
                    "lower(name) IN ('gpkg_contents', 'gpkg_geometry_columns')",
                    source);
    check.Step();
    if (sqlite3_column_int(check.get(), 0) != 2) {
      throw InputError(source +
                       ": not a GeoPackage (an SQLite database without the tables gpkg_contents "
                       "and gpkg_geometry_columns)");
    }
  }
  Statement list(db,
                 "SELECT g.table_name, g.column_name, g.geometry_type_name, g.srs_id "
                 "FROM gpkg_contents c JOIN gpkg_geometry_columns g "
                 "ON lower(c.table_name) = lower(g.table_name) "
                 "WHERE lower(c.data_type) = 'features' ORDER BY c.rowid",
                 source);
  std::vector<Layer> layers, areal;
  while (list.Step()) {
    Layer layer{list.Text(0), list.Text(1), list.Text(2), sqlite3_column_int64(list.get(), 3)};
    if (!wanted.empty() && internal::ToLower(layer.table) == internal::ToLower(wanted)) {
      return layer;
    }
    if (MayHoldPolygons(layer.geometry_type)) areal.push_back(layer);
    layers.push_back(std::move(layer));
  }
  if (!wanted.empty()) {
    throw InputError(source + ": no feature layer '" + wanted + "' (its layers: " +
                     (layers.empty() ? std::string("none") : LayerList(layers)) + ")");
  }
  if (layers.empty()) throw InputError(source + ": no feature layer (nothing to read)");
  if (areal.size() == 1) return areal.front();
  if (areal.empty()) {
    throw InputError(source + ": no layer of polygons (its layers: " + LayerList(layers) +
                     ", of points or lines)");
  }
  throw InputError(source + ": holds " + std::to_string(areal.size()) + " layers of polygons (" +
                   LayerList(areal) + "): name one as " + source + "|layername=NAME");
}

// The layer's spatial reference system's definition, "" if it has none.
std::string CrsDefinition(sqlite3* db, const std::string& source, long long srs_id) {
  Statement find(
      db, "SELECT definition FROM gpkg_spatial_ref_sys WHERE srs_id = " + std::to_string(srs_id),
      source);
  return find.Step() ? find.Text(0) : std::string();
}

// The Well-Known Binary inside a GeoPackageBinary blob (OGC 12-128r18, Sec. 2.1.3): the magic
// "GP", a version, a flags byte (byte order of the header, envelope kind, empty flag, extended
// type), the SRS id and the envelope, then the WKB. Returns false for a geometry flagged empty.
bool WkbOf(const unsigned char* blob, size_t size, const std::string& where,
           const unsigned char** wkb, size_t* wkb_size) {
  if (size < 8 || blob[0] != 'G' || blob[1] != 'P') {
    throw InputError(where +
                     ": the geometry is no GeoPackageBinary (which starts with 'GP', a version, "
                     "flags and an SRS id: 8 bytes)");
  }
  if (blob[2] != 0) {
    throw InputError(where + ": GeoPackageBinary version " + std::to_string(blob[2]) +
                     " (expected 0, of GeoPackage 1)");
  }
  const unsigned char flags = blob[3];
  if ((flags & 0x20) != 0) {
    throw InputError(where +
                     ": an extended geometry type (a GeoPackage extension's own "
                     "encoding; not supported)");
  }
  static const size_t kEnvelopeBytes[] = {0, 32, 48, 48, 64};
  const int envelope = (flags >> 1) & 7;
  if (envelope > 4) {
    throw InputError(where + ": GeoPackageBinary envelope kind " + std::to_string(envelope) +
                     " (expected 0 - 4)");
  }
  const size_t header = 8 + kEnvelopeBytes[envelope];
  if (size < header) {
    throw InputError(where + ": truncated GeoPackageBinary: its header and envelope need " +
                     std::to_string(header) + " bytes, the geometry has " + std::to_string(size));
  }
  if ((flags & 0x10) != 0) return false;
  *wkb = blob + header;
  *wkb_size = size - header;
  return true;
}

// A column's value as JSON: numbers, text (invalid UTF-8 replaced when written), null for NULL
// and BLOB.
nlohmann::ordered_json ValueOf(sqlite3_stmt* row, int column) {
  switch (sqlite3_column_type(row, column)) {
    case SQLITE_INTEGER:
      return sqlite3_column_int64(row, column);
    case SQLITE_FLOAT: {
      const double value = sqlite3_column_double(row, column);
      return std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json();
    }
    case SQLITE_TEXT:
      return reinterpret_cast<const char*>(sqlite3_column_text(row, column));
    default:
      return nullptr;
  }
}

GeoPackageLayer ReadLayer(sqlite3* db, const std::string& source, const std::string& wanted,
                          bool skip_non_areal, bool with_properties) {
  const Layer layer = ChooseLayer(db, source, wanted);
  GeoPackageLayer out;
  out.name = layer.table;
  out.crs_wkt = CrsDefinition(db, source, layer.srs_id);
  // The columns: the integer primary key (the feature id), the geometry, the attributes.
  std::string id_column;
  std::vector<std::string> attributes;
  {
    Statement columns(db, "PRAGMA table_info(" + Quoted(layer.table) + ")", source);
    while (columns.Step()) {
      const std::string name = columns.Text(1);
      if (sqlite3_column_int(columns.get(), 5) == 1 && id_column.empty() &&
          internal::ToLower(columns.Text(2)) == "integer") {
        id_column = name;
      } else if (internal::ToLower(name) != internal::ToLower(layer.geometry_column)) {
        attributes.push_back(name);
      }
    }
  }
  std::string sql = "SELECT " + (id_column.empty() ? std::string("NULL") : Quoted(id_column)) +
                    ", " + Quoted(layer.geometry_column);
  if (with_properties) {
    for (const std::string& name : attributes) sql += ", " + Quoted(name);
  }
  sql += " FROM " + Quoted(layer.table);
  if (!id_column.empty()) sql += " ORDER BY " + Quoted(id_column);
  Statement rows(db, sql, source);
  const std::string in_layer = source + ": layer '" + layer.table + "'";
  internal::SkippedGeometries skipped;
  std::string first_unclosed;
  int unclosed = 0;
  int groups = 0;
  for (int feature = 0; rows.Step(); ++feature) {
    std::string feature_place = "feature " + std::to_string(feature);
    if (sqlite3_column_type(rows.get(), 0) == SQLITE_INTEGER) {
      feature_place += " (fid " + std::to_string(sqlite3_column_int64(rows.get(), 0)) + ")";
    }
    const std::string where = in_layer + ": " + feature_place;
    if (with_properties) {
      nlohmann::ordered_json properties = nlohmann::ordered_json::object();
      for (size_t k = 0; k < attributes.size(); ++k) {
        properties[attributes[k]] = ValueOf(rows.get(), static_cast<int>(k) + 2);
      }
      out.properties.push_back(
          properties.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace));
    }
    const int column_type = sqlite3_column_type(rows.get(), 1);
    if (column_type == SQLITE_NULL) continue;
    if (column_type != SQLITE_BLOB) {
      throw InputError(where + ": the geometry is no GeoPackageBinary (a BLOB), found " +
                       (column_type == SQLITE_TEXT ? "text" : "a number"));
    }
    const auto* blob = static_cast<const unsigned char*>(sqlite3_column_blob(rows.get(), 1));
    const size_t size = static_cast<size_t>(sqlite3_column_bytes(rows.get(), 1));
    const unsigned char* wkb = nullptr;
    size_t wkb_size = 0;
    if (!WkbOf(blob, size, where, &wkb, &wkb_size)) continue;
    WkbPolygons read = ReadWkb(wkb, wkb_size, where);
    if (!read.non_areal.empty() && !skip_non_areal) {
      throw InputError(where + ": a " + read.non_areal.front().first +
                       " has no area (only polygons are read here)");
    }
    for (const auto& [type, count] : read.non_areal) skipped.Add(type, feature_place, count);
    if (read.unclosed_rings > 0 && unclosed == 0) first_unclosed = where;
    unclosed += read.unclosed_rings;
    int last_group = -1;
    for (size_t k = 0; k < read.polygons.size(); ++k) {
      out.polygons.push_back(std::move(read.polygons[k]));
      out.features.push_back(feature);
      const int group = read.multipolygons[k];
      out.multipolygons.push_back(group < 0 ? -1 : groups + group);
      last_group = std::max(last_group, group);
    }
    groups += last_group + 1;
  }
  if (!skipped.empty()) out.warnings.push_back(skipped.Note(in_layer));
  if (unclosed > 0) {
    out.warnings.push_back(first_unclosed + ": a ring without its closing point, taken as it is (" +
                           std::to_string(unclosed) + " in the layer)");
  }
  return out;
}

}  // namespace

std::pair<std::string, std::string> SplitLayerName(const std::string& path) {
  static const std::string kMarker = "|layername=";
  const size_t at = path.rfind(kMarker);
  if (at == std::string::npos) return {path, ""};
  return {path.substr(0, at), path.substr(at + kMarker.size())};
}

GeoPackageLayer ReadGeoPackage(const std::string& file, const std::string& layer,
                               bool skip_non_areal, bool with_properties) {
  OpenFile(file);  // The common message for a missing or unreadable file.
  sqlite3* handle = nullptr;
  const int status = sqlite3_open_v2(file.c_str(), &handle, SQLITE_OPEN_READONLY, nullptr);
  Database db(handle, &sqlite3_close);
  if (status != SQLITE_OK) {
    throw InputError(file + ": cannot open as a GeoPackage: " +
                     (handle != nullptr ? sqlite3_errmsg(handle) : sqlite3_errstr(status)));
  }
  return ReadLayer(db.get(), file, layer, skip_non_areal, with_properties);
}

GeoPackageLayer ReadGeoPackageBytes(const std::string& bytes, const std::string& source,
                                    const std::string& layer, bool skip_non_areal,
                                    bool with_properties) {
  sqlite3* handle = nullptr;
  if (sqlite3_open_v2(":memory:", &handle, SQLITE_OPEN_READWRITE, nullptr) != SQLITE_OK) {
    sqlite3_close(handle);
    throw std::bad_alloc();
  }
  Database db(handle, &sqlite3_close);
  auto* image = static_cast<unsigned char*>(sqlite3_malloc64(std::max<size_t>(bytes.size(), 1)));
  if (image == nullptr) throw std::bad_alloc();
  std::memcpy(image, bytes.data(), bytes.size());
  // A database in WAL mode (its header's bytes 18 and 19 are 2) is read as in rollback mode:
  // these bytes are the whole database, there is no write-ahead log beside them.
  if (bytes.size() >= 100 && image[18] == 2 && image[19] == 2) image[18] = image[19] = 1;
  const int status =
      sqlite3_deserialize(db.get(), "main", image, static_cast<sqlite3_int64>(bytes.size()),
                          static_cast<sqlite3_int64>(bytes.size()),
                          SQLITE_DESERIALIZE_FREEONCLOSE | SQLITE_DESERIALIZE_READONLY);
  if (status != SQLITE_OK) {
    throw InputError(source + ": not a readable GeoPackage: " + sqlite3_errmsg(db.get()));
  }
  return ReadLayer(db.get(), source, layer, skip_non_areal, with_properties);
}

}  // namespace acdplan::acd
