#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace scanfilter {

// Bad input, located: which file, which line, which field, what was wrong.
// what() reads "FILE:LINE: FIELD: PROBLEM" so an editor can jump to it.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::size_t line, std::string field, std::string problem)
      : std::runtime_error(format(file, line, field, problem)),
        file_(std::move(file)),
        line_(line),
        field_(std::move(field)),
        problem_(std::move(problem)) {}

  const std::string& file() const { return file_; }
  std::size_t line() const { return line_; }
  const std::string& field() const { return field_; }
  const std::string& problem() const { return problem_; }

 private:
  static std::string format(const std::string& file, std::size_t line, const std::string& field,
                            const std::string& problem) {
    // append() rather than operator+: GCC 12 warns falsely (-Wrestrict) on the latter.
    std::string out = file;
    if (line > 0) out.append(":").append(std::to_string(line));
    out.append(": ");
    if (!field.empty()) out.append(field).append(": ");
    return out.append(problem);
  }

  std::string file_;
  std::size_t line_;
  std::string field_;
  std::string problem_;
};

}  // namespace scanfilter
