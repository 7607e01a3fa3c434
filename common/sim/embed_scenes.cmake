# Writes OUT: a C++ table of every SCENE_DIR/*.yaml as (name, text).
file(GLOB files ${SCENE_DIR}/*.yaml)
list(SORT files)
set(body "")
foreach(f ${files})
  get_filename_component(name ${f} NAME_WE)
  file(READ ${f} text)
  string(APPEND body "  {\"${name}\", R\"scene(${text})scene\"},\n")
endforeach()
file(WRITE ${OUT} "// Generated from config/scenes by embed_scenes.cmake; do not edit.\n"
  "#include <string_view>\n#include <utility>\n#include <vector>\n"
  "namespace scanfilter::sim {\n"
  "const std::vector<std::pair<std::string_view, std::string_view>>& builtinSceneTexts() {\n"
  "  static const std::vector<std::pair<std::string_view, std::string_view>> scenes = {\n${body}  };\n"
  "  return scenes;\n}\n}  // namespace scanfilter::sim\n")
