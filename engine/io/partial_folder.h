#pragma once
#include <filesystem>

namespace hdprior {

// A folder written under a hidden temporary name beside its final place (".<name>.partial", which
// log discovery never enters) and renamed into place when complete, so a reader sees all of it or
// none of it. Dropped without publish(), the temporary folder is removed.
class PartialFolder {
 public:
  // Starts an empty temporary folder for `finalPath` (removing one left by an earlier attempt).
  // Throws Error naming the folder when it cannot be created.
  explicit PartialFolder(std::filesystem::path finalPath);
  ~PartialFolder();
  PartialFolder(const PartialFolder&) = delete;
  PartialFolder& operator=(const PartialFolder&) = delete;

  // Where to write.
  const std::filesystem::path& path() const { return temp_; }

  // Replaces whatever is at the final path with the folder; throws Error if the rename fails.
  const std::filesystem::path& publish();

 private:
  std::filesystem::path final_, temp_;
  bool published_ = false;
};

}  // namespace hdprior
