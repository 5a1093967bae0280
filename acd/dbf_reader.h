#pragma once
// The attribute table (.dbf) beside a shapefile's .shp: one row per shape record.

#include <istream>
#include <string>
#include <vector>

namespace acdplan::acd {

/// How the text of a .dbf's character fields is encoded; ReadDbf() gives UTF-8.
enum class DbfEncoding {
  kAuto,         ///< Decided by ReadDbf() from the table (see there).
  kUtf8,         ///< UTF-8; other bytes are an error.
  kWindows1252,  ///< Windows-1252 (ESRI's "ANSI"): Latin-1 with text in 0x80-0x9F.
  kLatin1,       ///< ISO-8859-1: each byte is the code point of the same number.
};

/// The encoding a shapefile's .cpg file names (its whole text, e.g. "UTF-8\n", "1252",
/// "ISO-8859-1", "88591", "65001", any case, surrounding blanks ignored); kAuto for an empty or
/// unknown name. Spellings differ only in '-', '_' and blanks: UTF-8 is "UTF8" or "65001";
/// Windows-1252 "1252", "CP1252", "WINDOWS1252", "WIN1252" or "ANSI1252"; Latin-1 "88591",
/// "ISO88591", "LATIN1" or "28591".
DbfEncoding DbfEncodingFromCpg(const std::string& cpg_text);

/// Reads a dBase III table (.dbf), as the ESRI Shapefile Technical Description (1998) uses it
/// for a shapefile's attributes: the 32-byte header, 32-byte field descriptors up to a 0x0D
/// byte, then from the header length on, the records of one deletion-flag byte and the fields'
/// bytes. Any version byte whose low three bits are 3 (0x03, 0x83 and 0x8B: with a memo file)
/// is taken; other tables (dBase IV-7, Visual FoxPro) and other files are errors. A character
/// field's length may use the decimal-count byte as its high byte (Clipper's and FoxPro's text
/// longer than 255 bytes, as shapelib reads it).
///
/// Returns per record, in file order, its attributes as the text of a JSON object (fields in
/// the file's order, as nlohmann::ordered_json's dump() writes it), e.g.
/// {"AREA":0.114,"NAME":"Ashe","CRESS_ID":5}. Values by field type:
///  - C (character): the text with trailing blanks and NULs trimmed (leading blanks kept), as a
///    string in UTF-8 (below); blank text is null, as GDAL reads it (dBase has no null).
///  - N, F (number): blanks and NULs around trimmed; empty, only '*' (an overflow) or only '.'
///    is null; else the whole text must be one decimal number (optional sign, digits, optional
///    point and digits, optional exponent): an integer when it has no '.', 'e' or 'E' and fits
///    in 64 bits, else a double ("1825.000" is 1825.0).
///  - L (logical): T, t, Y, y are true; F, f, N, n false; '?' or blank null.
///  - D (date): YYYYMMDD becomes "YYYY-MM-DD"; all blanks or all zeros is null.
///  - any other type (M memo, whose text lives in a .dbt file; B, G, I, ...): left out of
///    every record, with one warning per such field.
/// Deleted records ('*' flag; any other flag is a live record, as shapelib reads it) are
/// returned with the others, because row k belongs to the .shp's record k + 1 either way.
///
/// Text encoding (of character fields and field names), output always UTF-8: kUtf8 requires
/// valid UTF-8; kLatin1 maps each byte to its code point; kWindows1252 maps 0x80-0x9F by the
/// Windows-1252 table, and its five undefined bytes (0x81, 0x8D, 0x8F, 0x90, 0x9D) become
/// U+FFFD with one warning (an attribute is kept for output, not worth failing a read over);
/// kAuto takes Windows-1252 when the language driver (byte 29) is 0x03 (Windows ANSI) or 0x57
/// (ESRI's "ANSI", GDAL's default), else UTF-8 if every name and character value is valid
/// UTF-8, else Windows-1252 with one warning.
///
/// Messages: "<source>: byte B: <rule>" for the header and field descriptors (fields counted
/// from 1 in file order, e.g. "field 3 'NAME' repeats field 1's name"; bytes of names that are
/// not printable ASCII shown as \xHH), "<source>: record R, field 'NAME': <rule>" for values
/// (R counted from 1, as the shapefile reader numbers records; row R - 1 of the result).
/// O(file size) time.
/// @param source  the file name used in messages.
/// @param encoding  how character fields are encoded, e.g. DbfEncodingFromCpg() of the .cpg.
/// @param warnings  if given, receives a line for what was read though untidy: fields of an
///        unknown type left out, deleted records kept, bytes after the last record other than
///        one 0x1A end-of-file mark, text read as Windows-1252 under kAuto for not being UTF-8,
///        bytes undefined in Windows-1252.
/// @throws InputError naming `source` and the byte or record and field: a file shorter than
///         the header, a version byte of no dBase III table, a header length past the file's
///         end or too short for its descriptors and their 0x0D terminator, a field of length 0,
///         an empty or repeated field name, a record length other than 1 + the fields' lengths,
///         a record cut off by the end of the file ("record R (byte B) is truncated"), a
///         number, logical or date that breaks the rules above, text that is not valid UTF-8
///         under kUtf8.
std::vector<std::string> ReadDbf(std::istream& in, const std::string& source,
                                 DbfEncoding encoding = DbfEncoding::kAuto,
                                 std::vector<std::string>* warnings = nullptr);

}  // namespace acdplan::acd
