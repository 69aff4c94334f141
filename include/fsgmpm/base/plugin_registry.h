#ifndef fsgmpm_base_plugin_registry_h
#define fsgmpm_base_plugin_registry_h

#include <deal.II/base/exceptions.h>

#include <map>
#include <string>
#include <vector>

namespace fsgmpm
{
  using namespace dealii;

  /**
   * Named plug-ins of one kind (material models, body shapes), in the
   * manner of ASPECT's plugins: each registers a name, a one-line
   * description and its factory functions, and the input selects it by
   * name. MaterialFactory and ShapeFactory keep one registry each, as a
   * function-local static so that registrations from other translation
   * units may run during static initialisation in any order.
   */
  template <typename Factory>
  class PluginRegistry
  {
  public:
    /// @p kind names the plug-ins in messages, e.g. "material model".
    explicit PluginRegistry(const std::string &kind)
      : kind(kind)
    {}

    /// Adds a plug-in. Throws if the name is empty, holds '|' or ',' (the
    /// separators of a parameter's selection pattern), or is taken.
    void
    add(const std::string &name,
        const std::string &description,
        const Factory     &factory)
    {
      AssertThrow(!name.empty()
                    && name.find_first_of("|,") == std::string::npos,
                  ExcMessage("A " + kind
                             + "'s name must be non-empty and hold neither "
                               "'|' nor ','; got '"
                             + name + "'."));
      AssertThrow(entries.count(name) == 0,
                  ExcMessage("A " + kind + " named '" + name
                             + "' is already registered; choose another "
                               "name."));
      entries.emplace(name, Entry{description, factory});
    }

    /// The registered names, sorted.
    std::vector<std::string>
    names() const
    {
      std::vector<std::string> result;
      for (const auto &entry : entries)
        result.push_back(entry.first);
      return result;
    }

    /// "name1|name2|..." for a Patterns::Selection.
    std::string
    pattern() const
    {
      std::string text;
      for (const auto &entry : entries)
        text += (text.empty() ? "" : "|") + entry.first;
      return text;
    }

    /// "name1: description1; name2: ..." for the parameter documentation.
    std::string
    documentation() const
    {
      std::string text;
      for (const auto &entry : entries)
        text += (text.empty() ? "" : "; ") + entry.first + ": "
                + entry.second.description;
      return text;
    }

    /// The factory of @p name; throws, naming @p parameter (e.g.
    /// "Bodies/Body 0/Shape") and the registered names, if there is none.
    const Factory &
    get(const std::string &name, const std::string &parameter) const
    {
      const auto entry = entries.find(name);
      if (entry == entries.end())
        {
          std::string known;
          for (const auto &e : entries)
            known += (known.empty() ? "" : ", ") + e.first;
          AssertThrow(false,
                      ExcMessage(parameter + " = " + name
                                 + " is not a registered " + kind
                                 + "; registered: " + known + "."));
        }
      return entry->second.factory;
    }

    /// Calls f(factory) for every plug-in, in the order of their names.
    template <typename Function>
    void
    for_each(const Function &f) const
    {
      for (const auto &entry : entries)
        f(entry.second.factory);
    }

  private:
    struct Entry
    {
      std::string description;
      Factory     factory;
    };
    std::string                  kind;
    std::map<std::string, Entry> entries;
  };
} // namespace fsgmpm

#endif
