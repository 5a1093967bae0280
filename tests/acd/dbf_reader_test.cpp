#include "acd/dbf_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "base/input_error.h"
#include "tests/data_paths.h"
#include "tests/input_error_of.h"

namespace acdplan::acd {
namespace {

// The names here carry "Dbf": this file shares a translation unit with other tests
// (tests/CMakeLists.txt), shapefile_reader_test.cpp among them.

using ::testing::ElementsAre;
using ::testing::HasSubstr;

using acdplan::test::kShapefiles;

struct DbfFieldSpec {
  std::string name;
  char type = 'C';
  int length = 10;
  int decimals = 0;
};

// A table as a writer lays it out, for DbfBytes().
struct DbfTable {
  std::vector<DbfFieldSpec> fields;
  // Per record, per field its text, padded to the field's length by DbfBytes() (numbers
  // right-aligned, everything else left-aligned) unless it is that long already.
  std::vector<std::vector<std::string>> records;
  std::vector<size_t> deleted;  // Records (from 0) flagged '*'.
  unsigned char version = 0x03;
  unsigned char language_driver = 0x00;
};

void AppendDbfLittleEndian(std::uint32_t value, int bytes, std::string* out) {
  for (int k = 0; k < bytes; ++k) out->push_back(static_cast<char>(value >> (8 * k) & 0xFF));
}

// The .dbf bytes of `table`, with the 0x1A end-of-file mark most writers put after it.
std::string DbfBytes(const DbfTable& table) {
  std::uint32_t record_length = 1;
  for (const DbfFieldSpec& field : table.fields) record_length += field.length;
  std::string bytes;
  bytes.push_back(static_cast<char>(table.version));
  bytes += std::string("\x7C\x01\x02", 3);  // Last update 2024-01-02: not read.
  AppendDbfLittleEndian(static_cast<std::uint32_t>(table.records.size()), 4, &bytes);
  AppendDbfLittleEndian(static_cast<std::uint32_t>(32 + 32 * table.fields.size() + 1), 2, &bytes);
  AppendDbfLittleEndian(record_length, 2, &bytes);
  bytes += std::string(17, '\0');
  bytes.push_back(static_cast<char>(table.language_driver));
  bytes += std::string(2, '\0');
  for (const DbfFieldSpec& field : table.fields) {
    std::string name = field.name;
    name.resize(11, '\0');
    bytes += name;
    bytes.push_back(field.type);
    bytes += std::string(4, '\0');
    bytes.push_back(static_cast<char>(field.length));
    bytes.push_back(static_cast<char>(field.decimals));
    bytes += std::string(14, '\0');
  }
  bytes.push_back('\x0D');
  for (size_t r = 0; r < table.records.size(); ++r) {
    const bool deleted =
        std::find(table.deleted.begin(), table.deleted.end(), r) != table.deleted.end();
    bytes.push_back(deleted ? '*' : ' ');
    for (size_t f = 0; f < table.fields.size(); ++f) {
      const DbfFieldSpec& field = table.fields[f];
      const std::string& text = table.records[r][f];
      const std::string blanks(text.size() < static_cast<size_t>(field.length)
                                   ? static_cast<size_t>(field.length) - text.size()
                                   : 0,
                               ' ');
      const bool number = field.type == 'N' || field.type == 'F';
      bytes += number ? blanks + text : text + blanks;
    }
  }
  bytes.push_back('\x1A');
  return bytes;
}

std::vector<std::string> ReadDbfBytes(const std::string& bytes,
                                      DbfEncoding encoding = DbfEncoding::kAuto,
                                      std::vector<std::string>* warnings = nullptr) {
  std::istringstream in(bytes);
  return ReadDbf(in, "parcels.dbf", encoding, warnings);
}

std::string DbfErrorOf(const std::string& bytes, DbfEncoding encoding = DbfEncoding::kAuto) {
  return acdplan::test::InputErrorOf([&] { ReadDbfBytes(bytes, encoding); });
}

// A table of one field of type `type` and one record per value.
DbfTable OneFieldTable(char type, int length, const std::vector<std::string>& values) {
  DbfTable table;
  table.fields = {{"VALUE", type, length, 0}};
  for (const std::string& value : values) table.records.push_back({value});
  return table;
}

// The "VALUE" of each row of ReadDbfBytes(), as JSON text.
std::vector<std::string> DbfValues(const DbfTable& table,
                                   DbfEncoding encoding = DbfEncoding::kAuto) {
  std::vector<std::string> values;
  for (const std::string& row : ReadDbfBytes(DbfBytes(table), encoding)) {
    values.push_back(nlohmann::ordered_json::parse(row).at("VALUE").dump());
  }
  return values;
}

TEST(DbfReaderTest, ReadsEachTypeInFieldOrder) {
  DbfTable table;
  table.fields = {{"NAME", 'C', 12},     {"AREA", 'N', 10, 3}, {"COUNT", 'N', 6},
                  {"RATIO", 'F', 12, 4}, {"OPEN", 'L', 1},     {"SURVEYED", 'D', 8}};
  table.records = {{"  Ashe", "0.114", "5", "-1.5e-3", "T", "19990731"}, {"", "", "", "", " ", ""}};
  std::vector<std::string> warnings;
  const std::vector<std::string> rows =
      ReadDbfBytes(DbfBytes(table), DbfEncoding::kAuto, &warnings);
  EXPECT_THAT(rows, ElementsAre(R"({"NAME":"  Ashe","AREA":0.114,"COUNT":5,"RATIO":-0.0015,)"
                                R"("OPEN":true,"SURVEYED":"1999-07-31"})",
                                R"({"NAME":null,"AREA":null,"COUNT":null,"RATIO":null,)"
                                R"("OPEN":null,"SURVEYED":null})"));
  EXPECT_THAT(warnings, ElementsAre());
  // The text is what ordered_json writes.
  for (const std::string& row : rows) EXPECT_EQ(nlohmann::ordered_json::parse(row).dump(), row);
}

// Blank text is null, as GDAL reads it.
TEST(DbfReaderTest, TrimsCharacterFieldsOfTrailingBlanksAndNuls) {
  const DbfTable table =
      OneFieldTable('C', 8,
                    {std::string("ab c\0\0\0\0", 8), std::string("x  \0 \0  ", 8), " lead",
                     std::string(8, ' '), std::string(8, '\0')});
  EXPECT_THAT(DbfValues(table), ElementsAre(R"("ab c")", R"("x")", R"(" lead")", "null", "null"));
}

TEST(DbfReaderTest, NumbersAreIntegersWithoutPointOrExponentElseDoubles) {
  const DbfTable table = OneFieldTable(
      'N', 24,
      {"5", "-3", "+7", "1825.000000000000000", "1825.", ".5", "-2.5E-2", "1.5e3", "12e2",
       "9223372036854775807", "99999999999999999999", "-0", std::string(" 42\0", 4)});
  EXPECT_THAT(DbfValues(table),
              ElementsAre("5", "-3", "7", "1825.0", "1825.0", "0.5", "-0.025", "1500.0", "1200.0",
                          "9223372036854775807", "1e+20", "0", "42"));
}

TEST(DbfReaderTest, EmptyOverflowAndLonePointNumbersAreNull) {
  for (const char type : {'N', 'F'}) {
    const DbfTable table =
        OneFieldTable(type, 6, {"", "******", "*", ".", std::string(6, '\0'), "0"});
    EXPECT_THAT(DbfValues(table), ElementsAre("null", "null", "null", "null", "null", "0")) << type;
  }
}

TEST(DbfReaderTest, LogicalsAndDates) {
  EXPECT_THAT(DbfValues(OneFieldTable('L', 1, {"T", "t", "Y", "y", "F", "f", "N", "n", "?", " "})),
              ElementsAre("true", "true", "true", "true", "false", "false", "false", "false",
                          "null", "null"));
  EXPECT_THAT(DbfValues(OneFieldTable('D', 8, {"20240229", "        ", "00000000"})),
              ElementsAre(R"("2024-02-29")", "null", "null"));
}

TEST(DbfReaderTest, ValuesBreakingTheirTypesRuleNameRecordAndField) {
  EXPECT_EQ(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"1", "1,5"}))),
            "parcels.dbf: record 2, field 'VALUE': malformed number '1,5'");
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"12abc"}))),
              HasSubstr("record 1, field 'VALUE': malformed number '12abc'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('F', 6, {"nan"}))),
              HasSubstr("record 1, field 'VALUE': non-finite number 'nan'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"-inf"}))),
              HasSubstr("record 1, field 'VALUE': non-finite number '-inf'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"1e400"}))),
              HasSubstr("record 1, field 'VALUE': number out of range '1e400'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"1 2"}))),
              HasSubstr("malformed number '1 2'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 6, {"-"}))),
              HasSubstr("malformed number '-'"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('L', 1, {"T", "T", "X"}))),
              HasSubstr("parcels.dbf: record 3, field 'VALUE': logical value 'X' is none of T, "
                        "t, Y, y (true), F, f, N, n (false), ? and blank (null)"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('D', 8, {"2024-1-2"}))),
              HasSubstr("record 1, field 'VALUE': date '2024-1-2' is not YYYYMMDD (8 digits)"));
  // Bytes that are not printable ASCII are shown as \xHH.
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('N', 4, {"1\xE9"}))),
              HasSubstr("malformed number '1\\xE9'"));
}

TEST(DbfReaderTest, DeletedRecordsAreKeptWithOneWarning) {
  DbfTable table = OneFieldTable('N', 3, {"1", "2", "3", "4"});
  table.deleted = {1, 3};
  std::vector<std::string> warnings;
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table), DbfEncoding::kAuto, &warnings),
              ElementsAre(R"({"VALUE":1})", R"({"VALUE":2})", R"({"VALUE":3})", R"({"VALUE":4})"));
  EXPECT_THAT(warnings, ElementsAre("parcels.dbf: 2 records marked deleted (the first record 2): "
                                    "read as the others, so that row k stays the .shp's record "
                                    "k + 1"));
}

TEST(DbfReaderTest, FieldsOfOtherTypesAreLeftOutWithAWarningEach) {
  DbfTable table;
  table.fields = {{"ID", 'N', 4}, {"NOTES", 'M', 10}, {"NAME", 'C', 5}, {"BLOB", 'B', 10}};
  table.records = {{"7", "123", "Ashe", "9"}, {"8", "", "Bath", ""}};
  std::vector<std::string> warnings;
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table), DbfEncoding::kAuto, &warnings),
              ElementsAre(R"({"ID":7,"NAME":"Ashe"})", R"({"ID":8,"NAME":"Bath"})"));
  EXPECT_THAT(warnings,
              ElementsAre("parcels.dbf: byte 64: field 2 'NOTES' has type 'M' (memo: its text is "
                          "in a .dbt file), which is not read: left out of every record",
                          "parcels.dbf: byte 128: field 4 'BLOB' has type 'B', which is not "
                          "read: left out of every record"));
}

TEST(DbfReaderTest, ZeroRecordsAndZeroFields) {
  DbfTable table;
  table.fields = {{"NAME", 'C', 5}};
  std::vector<std::string> warnings;
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table), DbfEncoding::kAuto, &warnings), ElementsAre());
  EXPECT_THAT(warnings, ElementsAre());
  table.fields.clear();
  table.records = {{}, {}};
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table)), ElementsAre("{}", "{}"));
}

TEST(DbfReaderTest, Windows1252IsConvertedToUtf8) {
  const DbfTable table =
      OneFieldTable('C', 12, {"S\xEDtio Novo", "\x80 5", "S\xE3o Bento", "\x93ok\x94"});
  const std::vector<std::string> expected = {"\"S\xC3\xADtio Novo\"", "\"\xE2\x82\xAC 5\"",
                                             "\"S\xC3\xA3o Bento\"",
                                             "\"\xE2\x80\x9Cok\xE2\x80\x9D\""};
  EXPECT_EQ(DbfValues(table, DbfEncoding::kWindows1252), expected);  // "Sítio Novo", "€ 5".
}

TEST(DbfReaderTest, BytesUndefinedInWindows1252BecomeReplacementCharactersWithAWarning) {
  const DbfTable table = OneFieldTable('C', 4, {"a", "\x81", "\x8D\x8F", "\x90\x9D"});
  std::vector<std::string> warnings;
  const std::vector<std::string> rows =
      ReadDbfBytes(DbfBytes(table), DbfEncoding::kWindows1252, &warnings);
  ASSERT_EQ(rows.size(), 4u);
  EXPECT_EQ(rows[1], "{\"VALUE\":\"\xEF\xBF\xBD\"}");  // U+FFFD.
  EXPECT_EQ(rows[3], "{\"VALUE\":\"\xEF\xBF\xBD\xEF\xBF\xBD\"}");
  EXPECT_THAT(warnings,
              ElementsAre("parcels.dbf: record 2, field 'VALUE': byte 0x81 is not defined in "
                          "Windows-1252: read as U+FFFD (and 4 more bytes like it)"));
}

TEST(DbfReaderTest, Latin1MapsEachByteToItsCodePoint) {
  const DbfTable table = OneFieldTable('C', 4, {"S\xEDo", "\x80"});
  EXPECT_THAT(DbfValues(table, DbfEncoding::kLatin1),
              ElementsAre("\"S\xC3\xADo\"", "\"\xC2\x80\""));  // U+0080, a C1 control.
}

TEST(DbfReaderTest, Utf8PassesThroughAndMustBeValid) {
  const DbfTable table = OneFieldTable('C', 12, {"S\xC3\xADtio", "\xE2\x82\xAC"});
  EXPECT_THAT(DbfValues(table, DbfEncoding::kUtf8),
              ElementsAre("\"S\xC3\xADtio\"", "\"\xE2\x82\xAC\""));
  EXPECT_EQ(DbfErrorOf(DbfBytes(OneFieldTable('C', 8, {"ok", "S\xEDtio"})), DbfEncoding::kUtf8),
            "parcels.dbf: record 2, field 'VALUE': text is not valid UTF-8 (byte 0xED at its "
            "byte 1)");
  // Overlong forms and surrogates are not UTF-8 either.
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('C', 4, {"\xC0\xAF"})), DbfEncoding::kUtf8),
              HasSubstr("not valid UTF-8 (byte 0xC0 at its byte 0)"));
  EXPECT_THAT(DbfErrorOf(DbfBytes(OneFieldTable('C', 4, {"\xED\xA0\x80"})), DbfEncoding::kUtf8),
              HasSubstr("not valid UTF-8 (byte 0xED at its byte 0)"));
  DbfTable bad_name = OneFieldTable('C', 4, {"x"});
  bad_name.fields[0].name = "\xC1REA";
  EXPECT_EQ(DbfErrorOf(DbfBytes(bad_name), DbfEncoding::kUtf8),
            "parcels.dbf: byte 32: field 1 '\\xC1REA': name is not valid UTF-8");
}

TEST(DbfReaderTest, AutoTakesTheLanguageDriverThenUtf8ThenWindows1252) {
  // "Sítio" in UTF-8 and in Windows-1252.
  const std::string utf8 = "S\xC3\xADtio", windows1252 = "S\xEDtio";
  DbfTable table = OneFieldTable('C', 8, {utf8});
  std::vector<std::string> warnings;
  EXPECT_THAT(DbfValues(table), ElementsAre("\"" + utf8 + "\""));
  // Language driver 0x57 (ESRI's ANSI) or 0x03 (Windows ANSI): Windows-1252, whatever the bytes.
  for (const unsigned char driver : {0x57, 0x03}) {
    table.language_driver = driver;
    EXPECT_THAT(DbfValues(table), ElementsAre("\"S\xC3\x83\xC2\xADtio\"")) << int{driver};
  }
  table = OneFieldTable('C', 8, {"plain", windows1252});
  table.language_driver = 0x4D;  // A Chinese code page, not one read here.
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table), DbfEncoding::kAuto, &warnings),
              ElementsAre(R"({"VALUE":"plain"})", "{\"VALUE\":\"" + utf8 + "\"}"));
  EXPECT_THAT(warnings, ElementsAre("parcels.dbf: record 2, field 'VALUE': text is not valid "
                                    "UTF-8 and the language driver (byte 29: 0x4D) names no code "
                                    "page: read as Windows-1252"));
}

TEST(DbfReaderTest, FieldNamesAreTrimmedAndDecodedLikeText) {
  DbfTable table;
  table.fields = {{std::string("AB\0CD", 5), 'N', 2}, {"\xC1REA ", 'N', 2}};
  table.records = {{"1", "2"}};
  EXPECT_THAT(ReadDbfBytes(DbfBytes(table), DbfEncoding::kWindows1252),
              ElementsAre("{\"AB\":1,\"\xC3\x81REA\":2}"));  // "ÁREA".
}

TEST(DbfReaderTest, CharacterFieldsLongerThan255BytesUseTheDecimalCount) {
  DbfTable table;
  table.fields = {{"TEXT", 'C', 300 % 256, 300 / 256}, {"ID", 'N', 3}};
  const std::string text = std::string(299, 'x') + "y";
  table.records = {{text, "7"}};
  std::string bytes = DbfBytes(table);
  // DbfBytes() counts the low byte alone in the record length.
  bytes[10] = static_cast<char>(304 % 256);
  bytes[11] = static_cast<char>(304 / 256);
  EXPECT_THAT(ReadDbfBytes(bytes), ElementsAre(R"({"TEXT":")" + text + R"(","ID":7})"));
}

TEST(DbfReaderTest, CpgFilesNameTheEncoding) {
  for (const char* text : {"UTF-8", "utf-8\n", "  UTF8\r\n", "65001", "\xEF\xBB\xBFUTF-8"}) {
    EXPECT_EQ(DbfEncodingFromCpg(text), DbfEncoding::kUtf8) << text;
  }
  for (const char* text : {"1252", "CP1252", "windows-1252", "ANSI 1252", "Win1252\n"}) {
    EXPECT_EQ(DbfEncodingFromCpg(text), DbfEncoding::kWindows1252) << text;
  }
  for (const char* text : {"ISO-8859-1", "88591", "8859_1", "iso88591", "LATIN1", "28591"}) {
    EXPECT_EQ(DbfEncodingFromCpg(text), DbfEncoding::kLatin1) << text;
  }
  for (const char* text : {"", " \n", "OEM", "UTF-16", "ISO-8859-15", "GBK"}) {
    EXPECT_EQ(DbfEncodingFromCpg(text), DbfEncoding::kAuto) << text;
  }
}

TEST(DbfReaderTest, VersionBytesOfDbaseIIITablesAreAccepted) {
  DbfTable table = OneFieldTable('N', 2, {"1"});
  for (const unsigned char version : {0x03, 0x83, 0x8B}) {
    table.version = version;
    EXPECT_THAT(ReadDbfBytes(DbfBytes(table)), ElementsAre(R"({"VALUE":1})")) << int{version};
  }
}

TEST(DbfReaderTest, BadHeadersNameTheByteAndTheRule) {
  DbfTable table;
  table.fields = {{"ID", 'N', 4}, {"NAME", 'C', 6}};
  table.records = {{"1", "Ashe"}, {"2", "Bath"}};
  const std::string good = DbfBytes(table);  // Header 97 bytes, records of 11.
  EXPECT_EQ(DbfErrorOf(good.substr(0, 20)),
            "parcels.dbf: byte 20: the file ends inside the 32-byte header of a dBase table");
  // A .shp's first bytes (file code 9994, big-endian).
  std::string shp = good;
  shp.replace(0, 4, std::string("\x00\x00\x27\x0A", 4));
  EXPECT_EQ(DbfErrorOf(shp),
            "parcels.dbf: byte 0: not a dBase table: version byte 0x00 (a dBase III table has "
            "0x03, or 0x83 or 0x8B with a memo file)");
  std::string dbase4 = good;
  dbase4[0] = 0x04;
  EXPECT_THAT(DbfErrorOf(dbase4), HasSubstr("byte 0: not a dBase table: version byte 0x04"));
  std::string long_header = good;
  long_header[8] = static_cast<char>(200);
  EXPECT_EQ(DbfErrorOf(long_header),
            "parcels.dbf: byte 8: header length 200 runs past the end of the file (120 bytes)");
  std::string short_header = good;
  short_header[8] = 80;  // Ends inside the second descriptor.
  EXPECT_EQ(DbfErrorOf(short_header),
            "parcels.dbf: byte 64: the header ends at byte 80 (its length, byte 8) before the "
            "0x0D byte that ends the field descriptors");
  std::string no_terminator = good;
  no_terminator[96] = ' ';
  no_terminator[8] = 96;  // The descriptors fill the header exactly: no room for 0x0D.
  EXPECT_THAT(
      DbfErrorOf(no_terminator),
      HasSubstr("byte 96: the header ends at byte 96 (its length, byte 8) before the 0x0D"));
  std::string zero_length = good;
  zero_length[64 + 16] = 0;
  EXPECT_EQ(DbfErrorOf(zero_length), "parcels.dbf: byte 80: field 2 'NAME' has length 0");
  std::string empty_name = good;
  empty_name[64] = '\0';
  EXPECT_EQ(DbfErrorOf(empty_name), "parcels.dbf: byte 64: field 2 has an empty name");
  std::string blank_name = good;
  blank_name.replace(64, 4, "    ");
  EXPECT_THAT(DbfErrorOf(blank_name), HasSubstr("byte 64: field 2 has an empty name"));
  std::string repeated = good;
  repeated.replace(64, 4, std::string("ID\0\0", 4));
  EXPECT_EQ(DbfErrorOf(repeated), "parcels.dbf: byte 64: field 2 'ID' repeats field 1's name");
  std::string record_length = good;
  record_length[10] = 12;
  EXPECT_EQ(DbfErrorOf(record_length),
            "parcels.dbf: byte 10: record length 12 differs from 1 + the fields' lengths, 11");
}

TEST(DbfReaderTest, TruncatedRecordsAndTrailingBytes) {
  const std::string good = DbfBytes(OneFieldTable('N', 4, {"1", "2", "3"}));  // Header 65.
  EXPECT_EQ(DbfErrorOf(good.substr(0, 65 + 5 + 3)),
            "parcels.dbf: record 2 (byte 70) is truncated: the file ends after 3 of its 5 bytes "
            "(the header declares 3 records)");
  std::string many = good;
  many[4] = many[5] = many[6] = many[7] = '\xFF';  // 2^32 - 1 records: no overflow.
  EXPECT_THAT(DbfErrorOf(many), HasSubstr("record 4 (byte 80) is truncated: the file ends after "
                                          "1 of its 5 bytes (the header declares 4294967295 "
                                          "records)"));
  std::vector<std::string> warnings;
  EXPECT_THAT(ReadDbfBytes(good.substr(0, good.size() - 1), DbfEncoding::kAuto, &warnings),
              ElementsAre(R"({"VALUE":1})", R"({"VALUE":2})", R"({"VALUE":3})"));
  EXPECT_THAT(warnings, ElementsAre());  // Without the 0x1A mark, as with it.
  ReadDbfBytes(good, DbfEncoding::kAuto, &warnings);
  EXPECT_THAT(warnings, ElementsAre());
  ReadDbfBytes(good + "junk", DbfEncoding::kAuto, &warnings);
  EXPECT_THAT(warnings, ElementsAre("parcels.dbf: byte 81: 4 bytes after the last record and its "
                                    "end-of-file mark (0x1A): ignored"));
  warnings.clear();
  ReadDbfBytes(good.substr(0, good.size() - 1) + "\n", DbfEncoding::kAuto, &warnings);
  EXPECT_THAT(warnings, ElementsAre("parcels.dbf: byte 80: 1 byte after the last record: ignored"));
}

// R sf's files, read by another reader (pyshp 2.3.1) for the expected values.
TEST(DbfReaderTest, ReadsNorthCarolinasCounties) {
  std::ifstream in(kShapefiles / "nc.dbf", std::ios::binary);
  std::vector<std::string> warnings;
  const std::vector<std::string> rows = ReadDbf(in, "nc.dbf", DbfEncoding::kAuto, &warnings);
  ASSERT_EQ(rows.size(), 100u);
  EXPECT_EQ(rows[0],
            R"({"AREA":0.114,"PERIMETER":1.442,"CNTY_":1825.0,"CNTY_ID":1825.0,"NAME":"Ashe",)"
            R"("FIPS":"37009","FIPSNO":37009.0,"CRESS_ID":5,"BIR74":1091.0,"SID74":1.0,)"
            R"("NWBIR74":10.0,"BIR79":1364.0,"SID79":0.0,"NWBIR79":19.0})");
  EXPECT_EQ(nlohmann::ordered_json::parse(rows[99]).at("NAME"), "Brunswick");
  EXPECT_EQ(nlohmann::ordered_json::parse(rows[99]).at("CRESS_ID"), 10);
  EXPECT_THAT(warnings, ElementsAre());
}

TEST(DbfReaderTest, ReadsOlindasCensusTractsInWindows1252) {
  std::ifstream in(kShapefiles / "olinda1.dbf", std::ios::binary);
  std::vector<std::string> warnings;
  const std::vector<std::string> rows = ReadDbf(in, "olinda1.dbf", DbfEncoding::kAuto, &warnings);
  ASSERT_EQ(rows.size(), 470u);
  EXPECT_EQ(rows[0], R"({"ID":28801.0,"CD_GEOCODI":"260960005000001","TIPO":"URBANO",)"
                     R"("CD_GEOCODB":"260960005020","NM_BAIR":"Ouro Preto","V014":1119})");
  // Language driver 0x57: read as Windows-1252, "S\xEDtio Novo" in the file.
  EXPECT_EQ(nlohmann::ordered_json::parse(rows[83]).at("NM_BAIR"), "S\xC3\xADtio Novo");
  EXPECT_EQ(nlohmann::ordered_json::parse(rows[85]).at("NM_BAIR"), "Caixa D'\xC3\x81gua");
  // A rural tract without a neighbourhood: blank text, null (GDAL 3.6 reads it so).
  EXPECT_TRUE(nlohmann::ordered_json::parse(rows[332]).at("NM_BAIR").is_null());
  EXPECT_THAT(warnings, ElementsAre());
}

}  // namespace
}  // namespace acdplan::acd
