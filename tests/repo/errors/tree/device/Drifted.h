#pragma once
// A header written against the error convention, for the check to refuse (tests/repo/CMakeLists.txt).
#include <string>

namespace fixture {

std::string validateDrifted(int value);
bool openDrifted(const std::string& path, std::string& error);
std::optional<int> readDrifted(const std::string& path, std::string& why);

}  // namespace fixture
