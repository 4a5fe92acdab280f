#include "engine/io/partial_folder.h"

#include "engine/error.h"

namespace hdprior {
namespace fs = std::filesystem;

PartialFolder::PartialFolder(fs::path finalPath)
    : final_(std::move(finalPath)), temp_(final_.parent_path() / ("." + final_.filename().string() + ".partial")) {
  std::error_code ec;
  fs::remove_all(temp_, ec);
  fs::create_directories(temp_, ec);
  if (!fs::is_directory(temp_)) throw Error(temp_.string(), "cannot create the folder" + (ec ? ": " + ec.message() : ""));
}

PartialFolder::~PartialFolder() {
  if (published_) return;
  std::error_code ec;
  fs::remove_all(temp_, ec);
}

const fs::path& PartialFolder::publish() {
  std::error_code ec;
  fs::remove_all(final_, ec);
  fs::rename(temp_, final_, ec);
  if (ec) throw Error(final_.string(), "cannot rename the finished folder into place: " + ec.message());
  published_ = true;
  return final_;
}

}  // namespace hdprior
