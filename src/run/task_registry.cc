#include "run/task_registry.h"

#include "base/input_error.h"

#include <map>

namespace DiskImpact
{
  namespace Tasks
  {
    namespace
    {
      /// Filled during static initialization, before main().
      std::map<std::string, TaskEntry> &
      registry()
      {
        static std::map<std::string, TaskEntry> tasks;
        return tasks;
      }
    } // namespace

    bool
    add(const TaskEntry &entry)
    {
      registry()[entry.name] = entry;
      return true;
    }

    std::vector<TaskEntry>
    all()
    {
      std::vector<TaskEntry> entries;
      for (const auto &[name, entry] : registry())
        entries.push_back(entry);
      return entries;
    }

    const TaskEntry &
    get(const std::string &name)
    {
      const auto found = registry().find(name);
      require(found != registry().end(), "there is no task '" + name + "'");
      return found->second;
    }

    void
    declare_parameters(dealii::ParameterHandler &prm)
    {
      std::string names, descriptions;
      for (const auto &[name, entry] : registry())
        {
          names += (names.empty() ? "" : "|") + name;
          descriptions += " '" + name + "': " + entry.description;
        }
      prm.declare_entry("Task",
                        "modal analysis",
                        dealii::Patterns::Selection(names),
                        "What to compute." + descriptions);
    }

    void
    declare_own_parameters(dealii::ParameterHandler &prm)
    {
      for (const auto &[name, entry] : registry())
        if (entry.declare_parameters)
          entry.declare_parameters(prm);
    }
  } // namespace Tasks
} // namespace DiskImpact
