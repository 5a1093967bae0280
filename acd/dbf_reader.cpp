#include "acd/dbf_reader.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "acd/internal/byte_order.h"
#include "acd/internal/text_parsing.h"
#include "base/file_io.h"
#include "base/format.h"
#include "base/input_error.h"

// The names at file scope here carry "Dbf" or are otherwise particular to this file: it shares
// one translation unit with the other readers (acd_inputs in acd/CMakeLists.txt).

namespace acdplan::acd {
namespace {

// The format's fixed numbers (dBase III, as the ESRI Shapefile Technical Description uses it).
constexpr std::int64_t kDbfHeaderBytes = 32;
constexpr std::int64_t kDbfDescriptorBytes = 32;
constexpr unsigned char kDbfDescriptorsEnd = 0x0D;
constexpr unsigned char kDbfEndOfFile = 0x1A;
constexpr int kDbfVersionAt = 0, kDbfCountAt = 4, kDbfHeaderLengthAt = 8, kDbfRecordLengthAt = 10,
              kDbfLanguageDriverAt = 29;

// One field descriptor.
struct DbfField {
  std::string raw_name;     // Bytes 0-10 up to the first NUL, trailing blanks trimmed.
  std::string name;         // In UTF-8, once the table's encoding is known.
  unsigned char type = 0;   // 'C', 'N', ...
  std::int64_t offset = 0;  // Of its first byte in a record, after the deletion flag.
  std::int64_t length = 0;
  std::int64_t descriptor = 0;  // The byte its descriptor starts at.
};

using internal::ByteAt;

std::string HexByte(unsigned byte) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  return std::string("0x") + kDigits[byte >> 4 & 0xF] + kDigits[byte & 0xF];
}

// `text` for a message, whatever its bytes: printable ASCII as it is, the rest as \xHH.
std::string PrintableBytes(std::string_view text) {
  std::string shown;
  for (const char c : text) {
    const auto byte = static_cast<unsigned char>(c);
    shown += byte >= 0x20 && byte < 0x7F ? std::string(1, c) : "\\x" + HexByte(byte).substr(2);
  }
  return shown;
}

bool IsDbfBlank(char c) { return c == ' ' || c == '\0'; }  // Some writers pad with NULs.

std::string_view TrimTrailingBlanks(std::string_view text) {
  while (!text.empty() && IsDbfBlank(text.back())) text.remove_suffix(1);
  return text;
}

std::string_view TrimBlanks(std::string_view text) {
  text = TrimTrailingBlanks(text);
  while (!text.empty() && IsDbfBlank(text.front())) text.remove_prefix(1);
  return text;
}

// The index of the first byte of `text` where it stops being UTF-8 (RFC 3629: no overlong
// forms, no surrogates, nothing past U+10FFFF), or npos if it is valid throughout. JSON output
// needs the strict form: nlohmann's dump() throws on anything else.
size_t InvalidUtf8At(std::string_view text) {
  size_t i = 0;
  while (i < text.size()) {
    const auto lead = static_cast<unsigned char>(text[i]);
    if (lead < 0x80) {
      ++i;
      continue;
    }
    size_t length = 0;
    unsigned char low = 0x80, high = 0xBF;  // The second byte's range.
    if (lead >= 0xC2 && lead <= 0xDF) {
      length = 2;
    } else if (lead >= 0xE0 && lead <= 0xEF) {
      length = 3;
      if (lead == 0xE0) low = 0xA0;   // Overlong below U+0800.
      if (lead == 0xED) high = 0x9F;  // Surrogates.
    } else if (lead >= 0xF0 && lead <= 0xF4) {
      length = 4;
      if (lead == 0xF0) low = 0x90;   // Overlong below U+10000.
      if (lead == 0xF4) high = 0x8F;  // Past U+10FFFF.
    } else {
      return i;
    }
    if (text.size() - i < length) return i;
    for (size_t k = 1; k < length; ++k) {
      const auto byte = static_cast<unsigned char>(text[i + k]);
      if (byte < (k == 1 ? low : 0x80) || byte > (k == 1 ? high : 0xBF)) return i;
    }
    i += length;
  }
  return std::string_view::npos;
}

void AppendUtf8(char32_t code_point, std::string* out) {
  if (code_point < 0x80) {
    out->push_back(static_cast<char>(code_point));
  } else if (code_point < 0x800) {
    out->push_back(static_cast<char>(0xC0 | code_point >> 6));
    out->push_back(static_cast<char>(0x80 | (code_point & 0x3F)));
  } else {  // Only the Basic Multilingual Plane is needed here.
    out->push_back(static_cast<char>(0xE0 | code_point >> 12));
    out->push_back(static_cast<char>(0x80 | (code_point >> 6 & 0x3F)));
    out->push_back(static_cast<char>(0x80 | (code_point & 0x3F)));
  }
}

// Windows-1252's bytes 0x80-0x9F, where it differs from Latin-1 (there C1 controls); 0 marks
// the five bytes it leaves undefined.
constexpr char32_t kWindows1252From0x80[32] = {
    0x20AC, 0,      0x201A, 0x0192, 0x201E, 0x2026, 0x2020, 0x2021, 0x02C6, 0x2030, 0x0160,
    0x2039, 0x0152, 0,      0x017D, 0,      0,      0x2018, 0x2019, 0x201C, 0x201D, 0x2022,
    0x2013, 0x2014, 0x02DC, 0x2122, 0x0161, 0x203A, 0x0153, 0,      0x017E, 0x0178};
constexpr char32_t kReplacementCharacter = 0xFFFD;

// Bytes undefined in Windows-1252, read as U+FFFD: reported once, naming the first.
struct UndefinedDbfBytes {
  long long count = 0;
  std::string first;  // Where, and which byte.
};

// `raw` in `encoding` (kUtf8 already checked, kWindows1252 or kLatin1) as UTF-8; `where`
// names it in the warning about the first undefined byte.
template <typename Where>
std::string DbfTextAsUtf8(std::string_view raw, DbfEncoding encoding, UndefinedDbfBytes* undefined,
                          Where&& where) {
  if (encoding == DbfEncoding::kUtf8) return std::string(raw);
  std::string text;
  text.reserve(raw.size());
  for (const char c : raw) {
    const auto byte = static_cast<unsigned char>(c);
    char32_t code_point = byte;
    if (encoding == DbfEncoding::kWindows1252 && byte >= 0x80 && byte <= 0x9F) {
      code_point = kWindows1252From0x80[byte - 0x80];
      if (code_point == 0) {
        code_point = kReplacementCharacter;
        if (undefined->count++ == 0) undefined->first = where() + ": byte " + HexByte(byte);
      }
    }
    AppendUtf8(code_point, &text);
  }
  return text;
}

// The JSON of an N or F field's text (trimmed), or "" with `problem` set.
std::string DbfNumberJson(std::string_view text, std::string* problem) {
  const auto only = [&](char c) {
    return std::all_of(text.begin(), text.end(), [c](char k) { return k == c; });
  };
  if (text.empty() || only('*') || only('.')) return "null";  // '*': the value overflowed.
  long long integer = 0;
  if (text.find_first_of(".eE") == std::string_view::npos && internal::ParseInt(text, integer)) {
    return std::to_string(integer);
  }
  // Also an integer too long for 64 bits, which a double holds approximately.
  double value = 0.0;
  const internal::NumberStatus status = internal::ParseDouble(text, value);
  if (status != internal::NumberStatus::kOk) {
    *problem = internal::NumberProblem(status, PrintableBytes(text));
    return "";
  }
  return nlohmann::ordered_json(value).dump();
}

// The JSON of an L field's text (trimmed), or "" with `problem` set.
std::string DbfLogicalJson(std::string_view text, std::string* problem) {
  if (text.empty() || text == "?") return "null";
  if (text.size() == 1) {
    switch (text[0]) {
      case 'T':
      case 't':
      case 'Y':
      case 'y':
        return "true";
      case 'F':
      case 'f':
      case 'N':
      case 'n':
        return "false";
      default:
        break;
    }
  }
  *problem = "logical value '" + PrintableBytes(text) +
             "' is none of T, t, Y, y (true), F, f, N, n (false), ? and blank (null)";
  return "";
}

// The JSON of a D field's text (trimmed), or "" with `problem` set.
std::string DbfDateJson(std::string_view text, std::string* problem) {
  const auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
  if (text.empty() || std::all_of(text.begin(), text.end(), [](char c) { return c == '0'; })) {
    return "null";
  }
  if (text.size() != 8 || !std::all_of(text.begin(), text.end(), is_digit)) {
    *problem = "date '" + PrintableBytes(text) + "' is not YYYYMMDD (8 digits)";
    return "";
  }
  return "\"" + std::string(text.substr(0, 4)) + "-" + std::string(text.substr(4, 2)) + "-" +
         std::string(text.substr(6, 2)) + "\"";
}

bool IsReadDbfType(unsigned char type) {
  return type == 'C' || type == 'N' || type == 'F' || type == 'L' || type == 'D';
}

// The field descriptors from byte 32 to the 0x0D byte, checked as ReadDbf() documents; the
// caller has checked that the header length lies within `bytes`.
std::vector<DbfField> ReadDbfFields(const std::string& bytes, std::int64_t header_length,
                                    const std::string& source) {
  std::vector<DbfField> fields;
  std::int64_t offset = 0;
  for (std::int64_t at = kDbfHeaderBytes;; at += kDbfDescriptorBytes) {
    if (at < header_length && ByteAt(bytes, at) == kDbfDescriptorsEnd) break;
    if (at + kDbfDescriptorBytes > header_length) {
      throw InputError(source + ": byte " + std::to_string(at) + ": the header ends at byte " +
                       std::to_string(header_length) + " (its length, byte " +
                       std::to_string(kDbfHeaderLengthAt) +
                       ") before the 0x0D byte that ends the field descriptors");
    }
    DbfField field;
    const std::string_view name_bytes(bytes.data() + at, 11);
    field.raw_name = std::string(TrimTrailingBlanks(name_bytes.substr(0, name_bytes.find('\0'))));
    field.type = static_cast<unsigned char>(ByteAt(bytes, at + 11));
    field.length = ByteAt(bytes, at + 16);
    // Clipper and FoxPro write text longer than 255 bytes with the decimal count as the
    // length's high byte; shapelib, and so GDAL, read it so.
    if (field.type == 'C') field.length += 256 * static_cast<std::int64_t>(ByteAt(bytes, at + 17));
    field.offset = offset;
    field.descriptor = at;
    const std::string number = "field " + std::to_string(fields.size() + 1);
    if (field.raw_name.empty()) {
      throw InputError(source + ": byte " + std::to_string(at) + ": " + number +
                       " has an empty name");
    }
    if (field.length == 0) {
      throw InputError(source + ": byte " + std::to_string(at + 16) + ": " + number + " '" +
                       PrintableBytes(field.raw_name) + "' has length 0");
    }
    offset += field.length;
    fields.push_back(std::move(field));
  }
  return fields;
}

// Where a table's parts lie, from its header and field descriptors.
struct DbfLayout {
  std::int64_t count = 0;  // Of records.
  std::int64_t header_length = 0;
  std::int64_t record_length = 0;
  unsigned language_driver = 0;
  std::vector<DbfField> fields;

  // The bytes of `field` in record `record` (from 0), within `bytes` by ReadDbfLayout().
  std::string_view Value(const std::string& bytes, std::int64_t record,
                         const DbfField& field) const {
    return std::string_view(bytes).substr(
        static_cast<size_t>(header_length + record * record_length + 1 + field.offset),
        static_cast<size_t>(field.length));
  }
  std::int64_t RecordsEnd() const { return header_length + count * record_length; }
};

// The header and descriptors of the table in `bytes`, checked as ReadDbf() documents, with
// every record within `bytes`.
DbfLayout ReadDbfLayout(const std::string& bytes, const std::string& source) {
  const auto size = static_cast<std::int64_t>(bytes.size());
  const auto at_byte = [&](std::int64_t at) { return source + ": byte " + std::to_string(at); };
  if (size < kDbfHeaderBytes) {
    throw InputError(at_byte(size) + ": the file ends inside the 32-byte header of a dBase table");
  }
  const unsigned version = ByteAt(bytes, kDbfVersionAt);
  if ((version & 0x07) != 3) {
    throw InputError(at_byte(kDbfVersionAt) + ": not a dBase table: version byte " +
                     HexByte(version) +
                     " (a dBase III table has 0x03, or 0x83 or 0x8B with a memo file)");
  }
  DbfLayout layout;
  layout.count = internal::LittleEndianUnsigned(bytes, kDbfCountAt, 4);
  layout.header_length = internal::LittleEndianUnsigned(bytes, kDbfHeaderLengthAt, 2);
  layout.record_length = internal::LittleEndianUnsigned(bytes, kDbfRecordLengthAt, 2);
  layout.language_driver = ByteAt(bytes, kDbfLanguageDriverAt);
  if (layout.header_length > size) {
    throw InputError(at_byte(kDbfHeaderLengthAt) + ": header length " +
                     std::to_string(layout.header_length) + " runs past the end of the file (" +
                     std::to_string(size) + " bytes)");
  }
  layout.fields = ReadDbfFields(bytes, layout.header_length, source);
  std::int64_t fields_length = 1;  // The deletion flag.
  for (const DbfField& field : layout.fields) fields_length += field.length;
  if (layout.record_length != fields_length) {
    throw InputError(at_byte(kDbfRecordLengthAt) + ": record length " +
                     std::to_string(layout.record_length) +
                     " differs from 1 + the fields' lengths, " + std::to_string(fields_length));
  }
  // At most 2^32 records of at most 2^16 bytes: no overflow in 64 bits.
  if (layout.RecordsEnd() > size) {
    const std::int64_t first_cut = (size - layout.header_length) / layout.record_length;
    const std::int64_t start = layout.header_length + first_cut * layout.record_length;
    throw InputError(source + ": record " + std::to_string(first_cut + 1) + " (byte " +
                     std::to_string(start) + ") is truncated: the file ends after " +
                     std::to_string(size - start) + " of its " +
                     std::to_string(layout.record_length) + " bytes (the header declares " +
                     Plural(layout.count, "record") + ")");
  }
  return layout;
}

// kAuto made definite as ReadDbf() documents, with a line in `notes` when the text, not being
// UTF-8, is read as Windows-1252 for want of a better guess.
DbfEncoding ChooseDbfEncoding(const std::string& bytes, const DbfLayout& layout,
                              const std::string& source, std::vector<std::string>* notes) {
  // Windows ANSI (0x03), or ESRI's "ANSI" (0x57, GDAL's default too): Windows-1252, or
  // Latin-1, which it extends only in 0x80-0x9F (C1 controls there, never text).
  if (layout.language_driver == 0x03 || layout.language_driver == 0x57) {
    return DbfEncoding::kWindows1252;
  }
  std::string first_invalid;
  for (size_t k = 0; k < layout.fields.size() && first_invalid.empty(); ++k) {
    const std::string& name = layout.fields[k].raw_name;
    if (InvalidUtf8At(name) != std::string_view::npos) {
      first_invalid = "field " + std::to_string(k + 1) + "'s name '" + PrintableBytes(name) + "'";
    }
  }
  for (std::int64_t record = 0; record < layout.count && first_invalid.empty(); ++record) {
    for (const DbfField& field : layout.fields) {
      if (field.type == 'C' && InvalidUtf8At(TrimTrailingBlanks(
                                   layout.Value(bytes, record, field))) != std::string_view::npos) {
        first_invalid = "record " + std::to_string(record + 1) + ", field '" +
                        PrintableBytes(field.raw_name) + "'";
        break;
      }
    }
  }
  if (first_invalid.empty()) return DbfEncoding::kUtf8;
  notes->push_back(source + ": " + first_invalid +
                   ": text is not valid UTF-8 and the language driver (byte 29: " +
                   HexByte(layout.language_driver) + ") names no code page: read as Windows-1252");
  return DbfEncoding::kWindows1252;
}

}  // namespace

DbfEncoding DbfEncodingFromCpg(const std::string& cpg_text) {
  std::string_view text(cpg_text);
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // A byte order mark.
  std::string name;
  for (const char c : text) {
    if (c == '-' || c == '_' || c == ' ' || (c >= '\t' && c <= '\r')) continue;
    name.push_back(c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c);
  }
  if (name == "UTF8" || name == "65001") return DbfEncoding::kUtf8;
  if (name == "1252" || name == "CP1252" || name == "WINDOWS1252" || name == "WIN1252" ||
      name == "ANSI1252") {
    return DbfEncoding::kWindows1252;
  }
  if (name == "88591" || name == "ISO88591" || name == "LATIN1" || name == "28591") {
    return DbfEncoding::kLatin1;
  }
  return DbfEncoding::kAuto;
}

std::vector<std::string> ReadDbf(std::istream& in, const std::string& source, DbfEncoding encoding,
                                 std::vector<std::string>* warnings) {
  const std::string bytes = ReadRest(in);
  DbfLayout layout = ReadDbfLayout(bytes, source);
  const auto at_byte = [&](std::int64_t at) { return source + ": byte " + std::to_string(at); };
  std::vector<std::string> notes;  // Collected here, handed over if wanted.

  const std::int64_t records_end = layout.RecordsEnd();
  const std::int64_t past = static_cast<std::int64_t>(bytes.size()) - records_end;
  const bool end_of_file_mark = past > 0 && ByteAt(bytes, records_end) == kDbfEndOfFile;
  if (past > (end_of_file_mark ? 1 : 0)) {
    notes.push_back(at_byte(records_end + end_of_file_mark) + ": " +
                    Plural(past - end_of_file_mark, "byte") + " after the last record" +
                    (end_of_file_mark ? " and its end-of-file mark (0x1A)" : "") + ": ignored");
  }
  std::int64_t deleted = 0, first_deleted = 0;
  for (std::int64_t record = 0; record < layout.count; ++record) {
    const std::int64_t flag = layout.header_length + record * layout.record_length;
    if (ByteAt(bytes, flag) == '*' && deleted++ == 0) first_deleted = record;
  }
  if (deleted > 0) {
    notes.push_back(source + ": " + Plural(deleted, "record") +
                    " marked deleted (the first record " + std::to_string(first_deleted + 1) +
                    "): read as the others, so that row k stays the .shp's record k + 1");
  }
  if (encoding == DbfEncoding::kAuto) encoding = ChooseDbfEncoding(bytes, layout, source, &notes);

  std::vector<DbfField>& fields = layout.fields;
  UndefinedDbfBytes undefined;
  std::map<std::string, size_t> numbers;  // Per decoded name, its field's index.
  for (size_t k = 0; k < fields.size(); ++k) {
    DbfField& field = fields[k];
    const std::string number =
        "field " + std::to_string(k + 1) + " '" + PrintableBytes(field.raw_name) + "'";
    if (encoding == DbfEncoding::kUtf8 && InvalidUtf8At(field.raw_name) != std::string_view::npos) {
      throw InputError(at_byte(field.descriptor) + ": " + number + ": name is not valid UTF-8");
    }
    field.name = DbfTextAsUtf8(field.raw_name, encoding, &undefined, [&] {
      return source + ": field " + std::to_string(k + 1) + "'s name";
    });
    const auto [repeated, inserted] = numbers.emplace(field.name, k);
    if (!inserted) {
      throw InputError(at_byte(field.descriptor) + ": " + number + " repeats field " +
                       std::to_string(repeated->second + 1) + "'s name");
    }
  }

  // The fields read, and each one's key as the JSON text writes it.
  std::vector<const DbfField*> read;
  std::vector<std::string> keys;
  for (size_t k = 0; k < fields.size(); ++k) {
    const DbfField& field = fields[k];
    if (IsReadDbfType(field.type)) {
      read.push_back(&field);
      keys.push_back(nlohmann::ordered_json(field.name).dump() + ":");
      continue;
    }
    const std::string type = PrintableBytes(std::string(1, static_cast<char>(field.type)));
    notes.push_back(at_byte(field.descriptor) + ": field " + std::to_string(k + 1) + " '" +
                    field.name + "' has type '" + type + "'" +
                    (field.type == 'M' ? " (memo: its text is in a .dbt file)" : "") +
                    ", which is not read: left out of every record");
  }

  std::vector<std::string> rows;
  rows.reserve(static_cast<size_t>(layout.count));  // At most the file's size.
  for (std::int64_t record = 0; record < layout.count; ++record) {
    std::string row = "{";
    for (size_t k = 0; k < read.size(); ++k) {
      const DbfField& field = *read[k];
      const std::string_view raw = layout.Value(bytes, record, field);
      const auto where = [&] {
        return source + ": record " + std::to_string(record + 1) + ", field '" + field.name + "'";
      };
      std::string value, problem;
      switch (field.type) {
        case 'C': {
          const std::string_view text = TrimTrailingBlanks(raw);
          const size_t invalid =
              encoding == DbfEncoding::kUtf8 ? InvalidUtf8At(text) : std::string_view::npos;
          if (invalid != std::string_view::npos) {
            problem = "text is not valid UTF-8 (byte " +
                      HexByte(static_cast<unsigned char>(text[invalid])) + " at its byte " +
                      std::to_string(invalid) + ")";
            break;
          }
          // dBase has no null; blank text is read as one, as GDAL does.
          value =
              text.empty()
                  ? "null"
                  : nlohmann::ordered_json(DbfTextAsUtf8(text, encoding, &undefined, where)).dump();
          break;
        }
        case 'L':
          value = DbfLogicalJson(TrimBlanks(raw), &problem);
          break;
        case 'D':
          value = DbfDateJson(TrimBlanks(raw), &problem);
          break;
        default:  // 'N', 'F'.
          value = DbfNumberJson(TrimBlanks(raw), &problem);
          break;
      }
      if (!problem.empty()) throw InputError(where() + ": " + problem);
      if (k > 0) row += ',';
      row += keys[k];
      row += value;
    }
    row += '}';
    rows.push_back(std::move(row));
  }
  if (undefined.count > 0) {
    notes.push_back(undefined.first + " is not defined in Windows-1252: read as U+FFFD" +
                    (undefined.count > 1
                         ? " (and " + Plural(undefined.count - 1, "more byte") + " like it)"
                         : std::string()));
  }
  if (warnings != nullptr) warnings->insert(warnings->end(), notes.begin(), notes.end());
  return rows;
}

}  // namespace acdplan::acd
