#pragma once
// Reads the two definitions of the project's DDS types, the IDL
// (idl/scanfilter_types.idl) and the ROS 2 .msg files (idl/msg/), into one
// form, so a test can tell whether they still agree field by field.
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace scanfilter::test {

// One field, its type spelt as a ROS 2 .msg spells it ("float64[]",
// "std_msgs/Header"; a type of the message's own package without it).
struct MessageField {
  std::string type;
  std::string name;
  bool operator==(const MessageField&) const = default;
};
using MessageFields = std::vector<MessageField>;

// The fields of a .msg file of `package`: comments and constants skipped,
// default values dropped.
MessageFields parseMsgFields(std::string_view msg_text, std::string_view package);

// Every struct of an IDL text, by its ROS 2 name: struct X_ in module
// P::msg::dds_ is "P/X". Comments, annotations, constants and typedefs are
// skipped. Throws std::runtime_error on text it cannot read.
std::map<std::string, MessageFields> parseIdlStructs(std::string_view idl_text);

// Empty when the IDL's fields and the .msg's agree in name, type and order;
// else a sentence naming the first field that differs.
std::string firstDifference(const MessageFields& idl, const MessageFields& msg);

}  // namespace scanfilter::test
