#ifndef fsgmpm_base_version_h
#define fsgmpm_base_version_h

#include <string>

namespace fsgmpm
{
  /// The git commit the library was built from (a short hash, with
  /// "-modified" when the working tree differed from it; "unknown" outside
  /// a git checkout), stamped at build time (cmake/git_commit.cmake).
  const char *
  git_commit();

  /// "0.1.0 (git 1a2b3c4d5e6f)": --version, command_line.txt, summary.json
  /// and checkpoints.
  inline std::string
  version_string()
  {
    return std::string(FSGMPM_VERSION) + " (git " + git_commit() + ")";
  }
} // namespace fsgmpm

#endif
