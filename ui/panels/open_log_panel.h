#pragma once
#include <filesystem>
#include <optional>
#include <string>

namespace hdprior::ui {

// Shown while no log is open: a directory-path input. `loading`: a log is being read (the
// input is disabled); `error`: why the last one failed. Returns a directory to open, once.
std::optional<std::filesystem::path> drawOpenLogPanel(bool loading, const std::string& error);

}  // namespace hdprior::ui
