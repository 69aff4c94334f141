#ifndef fsgmpm_scene_parameter_file_check_h
#define fsgmpm_scene_parameter_file_check_h

#include <deal.II/base/parameter_handler.h>

#include <istream>
#include <string>
#include <vector>

namespace fsgmpm
{
  /**
   * Check the structure of a parameter file against the declarations of
   * @p prm before ParameterHandler reads it, so that a mistake is reported
   * with what to fix: an undeclared entry or subsection names the
   * subsection it was met in and the nearest declared name; an entry or
   * subsection declared elsewhere says where; a subsection still open at
   * the end of the file (a missing `end`) and an `end` with no subsection
   * open are reported as such, with the line that opened the subsection.
   * Throws ExcMessage naming @p file_name and the line; returns if the
   * structure is sound (ParameterHandler then checks the values). A file
   * that includes another (`include`) is left to ParameterHandler.
   */
  void
  check_parameter_file(const dealii::ParameterHandler &prm,
                       std::istream                   &input,
                       const std::string              &file_name);

  /// The name among @p candidates nearest to @p name (edit distance,
  /// ignoring case), or "" if none is near enough to be a likely typo.
  std::string
  nearest_name(const std::string              &name,
               const std::vector<std::string> &candidates);
} // namespace fsgmpm

#endif
