# Writes OUT: a C++ function FUNCTION() returning every DIR/*.yaml as
# (name, text), so the binaries carry the built-in scenes and sensors.
file(GLOB files ${DIR}/*.yaml)
list(SORT files)
set(body "")
foreach(f ${files})
  get_filename_component(name ${f} NAME_WE)
  file(READ ${f} text)
  string(APPEND body "  {\"${name}\", R\"yaml(${text})yaml\"},\n")
endforeach()
file(WRITE ${OUT} "// Generated from ${DIR} by embed_yaml.cmake; do not edit.\n"
  "#include <string_view>\n#include <utility>\n#include <vector>\n"
  "namespace scanfilter::sim {\n"
  "const std::vector<std::pair<std::string_view, std::string_view>>& ${FUNCTION}() {\n"
  "  static const std::vector<std::pair<std::string_view, std::string_view>> texts = {\n${body}  };\n"
  "  return texts;\n}\n}  // namespace scanfilter::sim\n")
