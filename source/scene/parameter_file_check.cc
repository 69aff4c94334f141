#include <deal.II/base/exceptions.h>
#include <deal.II/base/utilities.h>

#include <fsgmpm/scene/parameter_file_check.h>
#include <fsgmpm/scene/parameter_path.h>

#include <algorithm>
#include <cctype>
#include <map>

namespace fsgmpm
{
  using namespace dealii;

  namespace
  {
    // What is declared in one subsection: its entries and subsections
    // (demangled names), by the subsection's path ("" the top level,
    // "Bodies/Body 0" below).
    struct Declared
    {
      std::vector<std::string> entries, subsections;
    };

    void
    collect(const boost::property_tree::ptree &node,
            const std::string                 &path,
            std::map<std::string, Declared>   &declared)
    {
      Declared &here = declared[path];
      for (const auto &[mangled, child] : node)
        {
          const std::string name = demangle_parameter_name(mangled);
          if (child.count("value") == 1)
            here.entries.push_back(name);
          else
            {
              here.subsections.push_back(name);
              collect(child, path.empty() ? name : path + "/" + name, declared);
            }
        }
    }

    std::string
    lower(std::string s)
    {
      for (char &c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
      return s;
    }

    unsigned int
    edit_distance(const std::string &a, const std::string &b)
    {
      std::vector<unsigned int> row(b.size() + 1);
      for (unsigned int j = 0; j <= b.size(); ++j)
        row[j] = j;
      for (unsigned int i = 1; i <= a.size(); ++i)
        {
          unsigned int diagonal = row[0];
          row[0]                = i;
          for (unsigned int j = 1; j <= b.size(); ++j)
            {
              const unsigned int up = row[j];
              row[j]                = std::min({row[j] + 1,
                                                row[j - 1] + 1,
                                                diagonal + (a[i - 1] != b[j - 1] ? 1u : 0u)});
              diagonal              = up;
            }
        }
      return row[b.size()];
    }

    std::string
    where(const std::string &path)
    {
      return path.empty() ? "at the top level" : "in subsection <" + path + ">";
    }

    // The paths of the subsections that declare @p name as an entry (or,
    // with @p as_subsection, as a subsection).
    std::vector<std::string>
    declared_in(const std::map<std::string, Declared> &declared,
                const std::string                     &name,
                const bool                             as_subsection)
    {
      std::vector<std::string> paths;
      for (const auto &[path, d] : declared)
        {
          const auto &names = as_subsection ? d.subsections : d.entries;
          if (std::find(names.begin(), names.end(), name) != names.end())
            paths.push_back(path);
        }
      return paths;
    }
  } // namespace



  std::string
  nearest_name(const std::string              &name,
               const std::vector<std::string> &candidates)
  {
    std::string  best;
    unsigned int best_distance = numbers::invalid_unsigned_int;
    for (const auto &c : candidates)
      {
        const unsigned int d = edit_distance(lower(name), lower(c));
        if (d < best_distance)
          {
            best_distance = d;
            best          = c;
          }
      }
    // A typo: a few characters wrong, not a different word.
    const unsigned int allowed
      = std::max<unsigned int>(2, static_cast<unsigned int>(name.size()) / 3);
    return best_distance <= allowed ? best : "";
  }



  void
  check_parameter_file(const ParameterHandler &prm,
                       std::istream           &input,
                       const std::string      &file_name)
  {
    std::map<std::string, Declared> declared;
    collect(parameter_tree(prm), "", declared);

    // The open subsections: name and the line that opened each.
    std::vector<std::pair<std::string, unsigned int>> open;
    const auto path_of = [&](const unsigned int depth) {
      std::string p;
      for (unsigned int i = 0; i < depth; ++i)
        p += (i > 0 ? "/" : "") + open[i].first;
      return p;
    };
    const auto fail = [&](const unsigned int line, const std::string &what) {
      AssertThrow(false,
                  ExcMessage("Line " + std::to_string(line) + " of <"
                             + file_name + ">: " + what));
    };

    std::string  raw, line;
    unsigned int line_number = 0, first_line = 0;
    while (std::getline(input, raw))
      {
        ++line_number;
        // A comment runs to the end of the line; a trailing backslash joins
        // the next line (ParameterHandler's rules).
        const auto hash = raw.find('#');
        if (hash != std::string::npos)
          raw.erase(hash);
        raw = Utilities::trim(raw);
        if (line.empty())
          first_line = line_number;
        if (!raw.empty() && raw.back() == '\\')
          {
            line += raw.substr(0, raw.size() - 1) + " ";
            continue;
          }
        line += raw;
        line                   = Utilities::trim(line);
        const std::string text = line;
        line.clear();
        if (text.empty())
          continue;

        const std::string keyword = text.substr(0, text.find_first_of(" \t"));
        const std::string rest
          = Utilities::trim(text.substr(std::min(text.size(), keyword.size())));
        const std::string here = path_of(open.size());
        if (keyword == "include" || keyword == "INCLUDE")
          return;
        if (keyword == "end" || keyword == "END")
          {
            if (open.empty())
              fail(first_line,
                   "<end> with no subsection open: an extra <end>, or a "
                   "<subsection ...> line missing above it.");
            open.pop_back();
          }
        else if (keyword == "subsection" || keyword == "SUBSECTION")
          {
            const auto &names = declared[here].subsections;
            if (std::find(names.begin(), names.end(), rest) == names.end())
              {
                std::string what = "there is no subsection <" + rest + "> "
                                   + where(here) + ".";
                const auto elsewhere = declared_in(declared, rest, true);
                const bool higher
                  = !open.empty()
                    && std::any_of(elsewhere.begin(),
                                   elsewhere.end(),
                                   [&](const std::string &p) {
                                     for (unsigned int d = 0; d < open.size();
                                          ++d)
                                       if (p == path_of(d))
                                         return true;
                                     return false;
                                   });
                if (higher)
                  what += " Is the <end> of subsection <" + open.back().first
                          + "> (opened at line "
                          + std::to_string(open.back().second)
                          + ") missing above it?";
                else if (!elsewhere.empty())
                  what
                    += " It is a subsection " + where(elsewhere.front()) + ".";
                else if (const std::string near = nearest_name(rest, names);
                         !near.empty())
                  what += " Did you mean <" + near + ">?";
                fail(first_line,
                     what
                       + " Run fsgmpm --print-parameters for every "
                         "subsection and entry.");
              }
            open.emplace_back(rest, first_line);
          }
        else if (keyword == "set" || keyword == "SET")
          {
            const auto equals = rest.find('=');
            if (equals == std::string::npos)
              fail(first_line,
                   "<set " + rest + "> has no <=>: write <set Name = value>.");
            const std::string name    = Utilities::trim(rest.substr(0, equals));
            const auto       &entries = declared[here].entries;
            if (std::find(entries.begin(), entries.end(), name)
                == entries.end())
              {
                std::string what
                  = "there is no entry <" + name + "> " + where(here) + ".";
                if (const std::string near = nearest_name(name, entries);
                    !near.empty())
                  what += " Did you mean <" + near + ">?";
                else if (const auto elsewhere
                         = declared_in(declared, name, false);
                         !elsewhere.empty())
                  what += " It is an entry " + where(elsewhere.front())
                          + (open.empty() ? "." : " (is an <end> misplaced?).");
                fail(first_line,
                     what
                       + " Run fsgmpm --print-parameters for every "
                         "subsection and entry.");
              }
          }
        else
          fail(first_line,
               "cannot read <" + text
                 + ">: a line is <set Name = value>, <subsection Name>, "
                   "<end> or a comment (#).");
      }
    if (!open.empty())
      fail(line_number,
           "the file ends with subsection <" + path_of(open.size())
             + "> still open: the <end> of subsection <" + open.back().first
             + "> (opened at line " + std::to_string(open.back().second)
             + ") is missing.");
  }
} // namespace fsgmpm
