// The project's types are defined twice, in idl/scanfilter_types.idl (what
// the services put on the wire) and in idl/msg/ (what a ROS 2 workspace
// builds to read them); the two must agree field by field. Read from the
// files, so a field added to both needs no change here.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "message_definitions.hpp"

namespace scanfilter::test {
namespace {

const std::filesystem::path kIdlDir = std::filesystem::path(SCANFILTER_SOURCE_DIR) / "idl";
const std::filesystem::path kIdlFile = kIdlDir / "scanfilter_types.idl";
const std::filesystem::path kMsgDir = kIdlDir / "msg";  // one folder per package

std::string readText(const std::filesystem::path& path) {
  std::ifstream in(path);
  EXPECT_TRUE(in) << "cannot read " << path;
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

struct MsgFile {
  std::string package;
  std::string type;  // "package/Name"
  std::filesystem::path path;
};

std::vector<MsgFile> msgFiles() {
  std::vector<MsgFile> files;
  for (const auto& package : std::filesystem::directory_iterator(kMsgDir))
    for (const auto& file : std::filesystem::directory_iterator(package.path()))
      if (file.path().extension() == ".msg") {
        const std::string name = package.path().filename().string();
        files.push_back({name, name + "/" + file.path().stem().string(), file.path()});
      }
  return files;
}

// The IDL's fields and the .msg's, for one .msg file of the repository.
std::string differenceFromIdl(const MsgFile& msg, const std::string& msg_text, const std::string& idl_text) {
  const auto structs = parseIdlStructs(idl_text);
  const auto idl = structs.find(msg.type);
  if (idl == structs.end()) return "no struct for " + msg.type + " in the IDL";
  return firstDifference(idl->second, parseMsgFields(msg_text, msg.package));
}

MsgFile labeledScanMsg() {
  for (const auto& msg : msgFiles())
    if (msg.type == "scanfilter_msgs/LabeledScan") return msg;
  ADD_FAILURE() << "no LabeledScan.msg under " << kMsgDir;
  return {};
}

// A field line of a .msg: two words before any comment, not a constant.
bool isFieldLine(const std::string& line) {
  std::istringstream words(line.substr(0, line.find('#')));
  std::string type, name;
  return (words >> type >> name) && line.find('=') == std::string::npos;
}

// The text with its n-th field line (0-based) replaced.
std::string withFieldLineReplaced(const std::string& msg_text, std::size_t n, const std::string& replacement) {
  std::istringstream lines(msg_text);
  std::ostringstream out;
  std::size_t field = 0;
  for (std::string line; std::getline(lines, line);) {
    if (isFieldLine(line) && field++ == n) line = replacement;
    out << line << "\n";
  }
  return out.str();
}

std::string fieldLine(const MessageField& field) { return field.type + " " + field.name; }

TEST(MessageDefinitions, EveryMsgFileAgreesWithTheIdlFieldByField) {
  const std::string idl_text = readText(kIdlFile);
  const auto files = msgFiles();
  ASSERT_FALSE(files.empty()) << "no .msg files under " << kMsgDir;
  for (const auto& msg : files) {
    const std::string difference = differenceFromIdl(msg, readText(msg.path), idl_text);
    EXPECT_TRUE(difference.empty()) << msg.path.filename().string() << " against " << kIdlFile.filename().string()
                                    << ": " << difference;
  }
}

TEST(MessageDefinitions, EveryStructOfAPackageWithMsgFilesHasOne) {
  const auto files = msgFiles();
  for (const auto& [type, fields] : parseIdlStructs(readText(kIdlFile))) {
    const std::string package = type.substr(0, type.find('/'));
    if (!std::filesystem::exists(kMsgDir / package)) continue;  // a standard ROS 2 type
    const bool has_msg = std::any_of(files.begin(), files.end(), [&](const MsgFile& f) { return f.type == type; });
    EXPECT_TRUE(has_msg) << type << " is in the IDL but has no .msg file";
    EXPECT_FALSE(fields.empty()) << type;
  }
}

TEST(MessageDefinitions, AnAlteredMsgCopyFailsNamingTheFirstFieldThatDiffers) {
  const MsgFile msg = labeledScanMsg();
  const std::string idl_text = readText(kIdlFile);
  const std::string msg_text = readText(msg.path);
  const MessageFields fields = parseMsgFields(msg_text, msg.package);
  ASSERT_GE(fields.size(), 3u);
  ASSERT_EQ(differenceFromIdl(msg, msg_text, idl_text), "") << "the files must agree before they are altered";
  const auto failure = [&](const std::string& altered) { return differenceFromIdl(msg, altered, idl_text); };
  const auto contains = [](const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  };

  MessageField renamed = fields[1];
  renamed.name += "_renamed";
  const std::string with_renamed = withFieldLineReplaced(msg_text, 1, fieldLine(renamed));
  EXPECT_TRUE(contains(failure(with_renamed), "field 2 differs: IDL `" + fieldLine(fields[1]) + "`"))
      << failure(with_renamed);

  const MessageField retyped{"wstring", fields[2].name};
  const std::string with_retyped = withFieldLineReplaced(msg_text, 2, fieldLine(retyped));
  EXPECT_TRUE(contains(failure(with_retyped), "field 3 differs")) << failure(with_retyped);
  EXPECT_TRUE(contains(failure(with_retyped), ".msg `" + fieldLine(retyped) + "`")) << failure(with_retyped);

  std::string swapped = withFieldLineReplaced(msg_text, 1, fieldLine(fields[2]));
  swapped = withFieldLineReplaced(swapped, 2, fieldLine(fields[1]));
  EXPECT_TRUE(contains(failure(swapped), "field 2 differs: IDL `" + fieldLine(fields[1]) + "`")) << failure(swapped);

  const std::size_t last = fields.size() - 1;
  const std::string dropped = withFieldLineReplaced(msg_text, last, "# dropped");
  EXPECT_TRUE(contains(failure(dropped), "`" + fieldLine(fields[last]) + "` is in the IDL only")) << failure(dropped);
}

TEST(MessageDefinitions, AnAlteredIdlCopyFailsNamingTheField) {
  const MsgFile msg = labeledScanMsg();
  const std::string idl_text = readText(kIdlFile);
  const MessageFields fields = parseIdlStructs(idl_text).at(msg.type);
  ASSERT_GE(fields.size(), 2u);
  // The second member of LabeledScan_, renamed where the struct declares it.
  std::string altered = idl_text;
  const std::size_t member = altered.find(" " + fields[1].name + ";", altered.find("struct LabeledScan_"));
  ASSERT_NE(member, std::string::npos);
  altered.insert(member + 1 + fields[1].name.size(), "_renamed");
  const std::string difference = differenceFromIdl(msg, readText(msg.path), altered);
  EXPECT_NE(difference.find("field 2 differs: IDL `" + fields[1].type + " " + fields[1].name + "_renamed`"),
            std::string::npos)
      << difference;
}

TEST(IdlParser, MapsTypesAsTheRos2MappingDoes) {
  const auto structs = parseIdlStructs(R"(
    #include "other.idl"
    module pkg { module msg { module dds_ {
      /* a block
         comment */
      struct Inner_ { long x; };  // trailing comment
      const long IGNORED = 3;
      struct Outer_ {
        @key unsigned long long id;
        long a; unsigned long b; long long c; short d; unsigned short e;
        double f; float g; boolean h; octet i; char j; string k; string<8> l;
        sequence<double> m; sequence<octet, 4> n; double o[36], p;
        pkg::msg::dds_::Inner_ q; Inner_ r; sequence<Inner_> s;
        std_msgs::msg::dds_::Header_ t; builtin_interfaces::msg::dds_::Time_ u;
      };
    }; }; };
  )");
  ASSERT_EQ(structs.size(), 2u);
  const MessageFields expected = {
      {"uint64", "id"},    {"int32", "a"},     {"uint32", "b"},      {"int64", "c"},   {"int16", "d"},
      {"uint16", "e"},     {"float64", "f"},   {"float32", "g"},     {"bool", "h"},    {"uint8", "i"},
      {"int8", "j"},       {"string", "k"},    {"string<=8", "l"},   {"float64[]", "m"}, {"uint8[<=4]", "n"},
      {"float64[36]", "o"}, {"float64", "p"},  {"Inner", "q"},       {"Inner", "r"},   {"Inner[]", "s"},
      {"std_msgs/Header", "t"}, {"builtin_interfaces/Time", "u"}};
  EXPECT_EQ(firstDifference(structs.at("pkg/Outer"), expected), "");
  EXPECT_EQ(structs.at("pkg/Outer"), expected);
}

TEST(MsgParser, SkipsCommentsAndConstantsAndDropsDefaults) {
  const MessageFields fields = parseMsgFields(R"(# header comment
int32 LIMIT=5
string NAME = "x"

pkg/Inner inner   # own package, written in full
std_msgs/Header header
string label "a # not a comment"
byte[] raw
float64[36] covariance
)",
                                              "pkg");
  const MessageFields expected = {{"Inner", "inner"},
                                  {"std_msgs/Header", "header"},
                                  {"string", "label"},
                                  {"uint8[]", "raw"},
                                  {"float64[36]", "covariance"}};
  EXPECT_EQ(fields, expected);
}

TEST(FirstDifference, NamesTheFirstFieldThatDiffers) {
  const MessageFields idl = {{"int32", "a"}, {"float64", "b"}, {"bool", "c"}};
  EXPECT_EQ(firstDifference(idl, idl), "");
  EXPECT_EQ(firstDifference(idl, {{"int32", "a"}, {"float32", "b"}, {"bool", "c"}}),
            "field 2 differs: IDL `float64 b` (as .msg types), .msg `float32 b`");
  EXPECT_EQ(firstDifference(idl, {{"int32", "a"}, {"bool", "c"}, {"float64", "b"}}),
            "field 2 differs: IDL `float64 b` (as .msg types), .msg `bool c`");
  EXPECT_EQ(firstDifference(idl, {{"int32", "a"}, {"float64", "b"}}), "field 3 `bool c` is in the IDL only");
  EXPECT_EQ(firstDifference({{"int32", "a"}}, {{"int32", "a"}, {"uint8", "d"}}),
            "field 2 `uint8 d` is in the .msg only");
}

}  // namespace
}  // namespace scanfilter::test
