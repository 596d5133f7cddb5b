#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/base/prm_entry_origins.h>
#include <bfemp/base/prm_include.h>
#include <bfemp/scene/scene_parameters.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <sstream>

namespace bfemp
{
  void
  declare_dimension(ParameterHandler &prm)
  {
    prm.declare_entry("dimension",
                      "2",
                      Patterns::Integer(2, 3),
                      "[-] Space dimension of the scene, 2 or 3; read first, "
                      "everything else follows it.");
  }



  namespace
  {
    /** deal.II exception text on one line, without the source-location
     *  preamble and the stack trace. */
    std::string
    what_deal_ii_says(const std::exception &error)
    {
      const std::string text   = error.what();
      const std::string marker = "Additional information: ";
      const auto        at     = text.find(marker);
      std::string       said =
        at == std::string::npos ? text : text.substr(at + marker.size());
      // The stack trace comes before the closing dashes.
      for (const char *tail : {"\nStacktrace:", "\n--------"})
        said = said.substr(0, said.find(tail));
      std::string one_line;
      for (const char c : said)
        if (!std::isspace(static_cast<unsigned char>(c)))
          one_line += c;
        else if (!one_line.empty() && one_line.back() != ' ')
          one_line += ' ';
      if (!one_line.empty() && one_line.back() == ' ')
        one_line.pop_back();
      return one_line;
    }



    /** A 'set' or 'subsection' line of a prm text, and where it is. */
    struct PrmStatement
    {
      std::vector<std::string> path;
      bool                     is_entry;
      std::string              name;
    };



    /** The statements in the first @p n_lines lines of @p in; @p path ends
     *  as the subsection path open after them. */
    std::vector<PrmStatement>
    scan_prm(std::istream             &in,
             const unsigned int        n_lines,
             std::vector<std::string> &path)
    {
      std::vector<PrmStatement> statements;
      std::string               line;
      for (unsigned int n = 0; n < n_lines && std::getline(in, line); ++n)
        {
          std::istringstream words(line.substr(0, line.find('#')));
          std::string        keyword, rest, name, word;
          words >> keyword;
          std::getline(words, rest);
          for (auto &c : keyword)
            c = std::tolower(static_cast<unsigned char>(c));
          std::istringstream name_words(
            keyword == "set" ? rest.substr(0, rest.find('=')) : rest);
          while (name_words >> word)
            name += (name.empty() ? "" : " ") + word;
          if (keyword == "set" || keyword == "subsection")
            statements.push_back({path, keyword == "set", name});
          if (keyword == "subsection")
            path.push_back(name);
          else if (keyword == "end" && !path.empty())
            path.pop_back();
        }
      return statements;
    }



    /** The entries (or subsections) that @p prm declares in @p path. */
    std::string
    declared_names(const ParameterHandler         &prm,
                   const std::vector<std::string> &path,
                   const bool                      entries)
    {
      std::stringstream text;
      prm.print_parameters(text,
                           ParameterHandler::OutputStyle(
                             ParameterHandler::ShortPRM |
                             ParameterHandler::KeepDeclarationOrder));
      std::vector<std::string> end_path;
      std::string              names;
      for (const PrmStatement &statement :
           scan_prm(text, std::numeric_limits<unsigned int>::max(), end_path))
        if (statement.path == path && statement.is_entry == entries)
          names += (names.empty() ? "" : ", ") + statement.name;
      return names.empty() ? "none" : names;
    }



    /** deal.II's "Line <n> of file <f>: ..." parse errors as "line n,
     *  subsection 'a/b', entry 'e' = v: what is allowed". */
    std::string
    explain_parse_error(const std::string      &said,
                        const ExpandedPrm      &expanded,
                        const std::string      &file,
                        const ParameterHandler &prm)
    {
      std::smatch line;
      if (!std::regex_match(said,
                            line,
                            std::regex("Line <([0-9]+)> of file <.*?>?: (.*)")))
        return file + ": " + said;
      // deal.II counts lines of the expanded text: name the file and line
      // the statement is written in; the open subsections are those of the
      // text up to it, includes and all.
      const unsigned int n = std::stoi(line[1]);
      const auto        &origin =
        expanded.origins[std::min<std::size_t>(n, expanded.origins.size()) - 1];
      std::istringstream       in(expanded.text);
      std::vector<std::string> path;
      scan_prm(in, n - 1, path);
      std::string where =
        origin.first + ": line " + std::to_string(origin.second) + ", ";
      if (path.empty())
        where += "top level";
      else
        {
          where += "subsection '" + path[0];
          for (unsigned int i = 1; i < path.size(); ++i)
            where += "/" + path[i];
          where += "'";
        }
      const std::string problem = line[2];
      std::smatch       m;
      if (std::regex_match(problem,
                           m,
                           std::regex("No entry with name <(.*)> was declared "
                                      "in the current subsection\\.")))
        return where + ", entry '" + m[1].str() +
               "': no such entry; the entries declared there are: " +
               declared_names(prm, path, true);
      if (std::regex_match(problem,
                           m,
                           std::regex("There is no such subsection to be "
                                      "entered: (.*)")))
        {
          // deal.II names it with its path, "body 0.materials".
          std::string name = m[1].str(), prefix;
          for (const std::string &p : path)
            prefix += p + ".";
          if (name.rfind(prefix, 0) == 0)
            name = name.substr(prefix.size());
          return where + ": no subsection '" + name +
                 "' is declared there; the subsections declared there are: " +
                 declared_names(prm, path, false);
        }
      if (std::regex_match(problem,
                           m,
                           std::regex("The entry value (.*) for the entry "
                                      "named (.*) does not match the given "
                                      "pattern: (.*)")))
        return where + ", entry '" + m[2].str() + "' = " + m[1].str() +
               ": does not match the allowed pattern " + m[3].str();
      return where + ": " + problem;
    }
  } // namespace



  void
  parse_prm_file(ParameterHandler  &prm,
                 const std::string &file,
                 const bool         lenient)
  {
    if (!std::filesystem::is_regular_file(file))
      throw InputError(file + ": no such parameter file");
    // bfemp expands the includes itself: a relative include path means a
    // file next to the including file (resolve_prm_include), and errors
    // name the file and line they are in.
    const ExpandedPrm expanded = expand_prm_includes(file);
    try
      {
        prm.parse_input_from_string(expanded.text, "", lenient);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &error)
      {
        throw InputError(
          explain_parse_error(what_deal_ii_says(error), expanded, file, prm));
      }
  }



  unsigned int
  read_dimension(const std::string &file)
  {
    ParameterHandler prm;
    declare_dimension(prm);
    parse_prm_file(prm, file, true);
    return prm.get_integer("dimension");
  }



  template <int dim>
  void
  SceneParameters<dim>::declare_parameters(
    ParameterHandler                                        &prm,
    const std::vector<typename BodyParameters<dim>::Counts> &body_counts,
    const unsigned int                                       n_level_sets,
    const std::vector<unsigned int> &motions_per_fem_body)
  {
    declare_dimension(prm);
    prm.declare_entry("number of bodies",
                      "1",
                      Patterns::Integer(0),
                      "[-] Number of MPM bodies, subsections 'body 0', 'body "
                      "1', ...");
    prm.declare_entry("number of FEM bodies",
                      "0",
                      Patterns::Integer(0),
                      "[-] Number of linear-simplex FEM bodies, subsections "
                      "'fem body 0', 'fem body 1', ...; they need an "
                      "implicit 'time/integrator'.");
    RunParameters::declare_parameters(prm);
    GridParameters<dim>::declare_parameters(prm);
    TimeParameters::declare_parameters(prm);
    TransferParameters::declare_parameters(prm);
    CmpmParameters::declare_parameters(prm);
    prm.enter_subsection("gravity");
    parameter_tools::declare_point<dim>(prm,
                                        "acceleration",
                                        parameter_tools::components<dim>(0,
                                                                         -9.81,
                                                                         0),
                                        "[m/s^2] Gravitational acceleration");
    prm.leave_subsection();
    GridBoundaries<dim>::declare_parameters(prm, n_level_sets);
    OutputParameters::declare_parameters(prm);
    CheckpointParameters::declare_parameters(prm);
    SolverParameters::declare_parameters(prm);
    ContactParameters::declare_parameters(prm);
    for (unsigned int b = 0; b < motions_per_fem_body.size(); ++b)
      {
        prm.enter_subsection(parameter_tools::numbered("fem body", b));
        FemBodyParameters<dim>::declare_parameters(prm,
                                                   motions_per_fem_body[b]);
        prm.leave_subsection();
      }
    for (unsigned int b = 0; b < body_counts.size(); ++b)
      {
        prm.enter_subsection(parameter_tools::numbered("body", b));
        BodyParameters<dim>::declare_parameters(prm, body_counts[b]);
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  SceneParameters<dim>::parse_parameters(ParameterHandler &prm)
  {
    run.parse_parameters(prm);
    grid.parse_parameters(prm);
    time.parse_parameters(prm);
    transfer.parse_parameters(prm);
    cmpm.parse_parameters(prm);
    prm.enter_subsection("gravity");
    gravity = parameter_tools::get_vector<dim>(prm, "acceleration");
    prm.leave_subsection();
    boundaries.parse_parameters(prm);
    output.parse_parameters(prm);
    checkpoint.parse_parameters(prm);
    const PrmEntryOrigins origins(file);
    bodies.resize(prm.get_integer("number of bodies"));
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const std::string name = parameter_tools::numbered("body", b);
        prm.enter_subsection(name);
        bodies[b].parse_parameters(prm, name, &origins);
        prm.leave_subsection();
      }
    solver.parse_parameters(prm);
    contact.parse_parameters(prm);
    fem_bodies.resize(prm.get_integer("number of FEM bodies"));
    for (unsigned int b = 0; b < fem_bodies.size(); ++b)
      {
        const std::string name = parameter_tools::numbered("fem body", b);
        prm.enter_subsection(name);
        fem_bodies[b].parse_parameters(prm,
                                       name,
                                       origins.directory_of({name, "mesh"},
                                                            "file"));
        prm.leave_subsection();
      }
    require_input(!bodies.empty() || !fem_bodies.empty(),
                  "top level",
                  "number of bodies",
                  "0",
                  "a scene needs at least one MPM body or one FEM body "
                  "('number of FEM bodies')");
    contact.check_bodies(bodies.size(), fem_bodies.size());
    if (cmpm.enabled)
      check_cmpm();
    require_input(fem_bodies.empty() || time.is_implicit() ||
                    time.is_substepped(),
                  "time",
                  "integrator",
                  "an explicit integrator",
                  "FEM bodies are integrated implicitly only: choose "
                  "'implicit backward Euler', 'implicit Newmark' or "
                  "'substepped explicit' (FEM bodies take the macro step "
                  "implicitly)");
  }



  template <int dim>
  void
  SceneParameters<dim>::check_cmpm() const
  {
    // What cMPM supports so far (doc/cmpm.md, "Status and limits"): the
    // implicit backward Euler with PIC; FEM bodies take part through the
    // barrier contact.
    require_input(time.is_implicit() &&
                    time.implicit_scheme().alpha *
                        (1. - 2. * time.implicit_scheme().beta) ==
                      0. &&
                    time.implicit_scheme().gamma == 1.,
                  "time",
                  "integrator",
                  time.is_implicit() ? "implicit Newmark"
                                     : "an explicit or substepped integrator",
                  "cMPM ('cmpm/enabled = true') runs with 'implicit backward "
                  "Euler' (seed 002 eqs. 5-6) so far");
    require_input(transfer.scheme == TransferParameters::Scheme::pic,
                  "transfer",
                  "scheme",
                  transfer.scheme == TransferParameters::Scheme::apic ? "APIC"
                                                                      : "FLIP",
                  "cMPM transfers with PIC so far (its inertia is the "
                  "consistent one over the particles)");
  }



  template <int dim>
  void
  SceneParameters<dim>::read(const std::string &prm_file)
  {
    file = prm_file;
    // Settle the counts of numbered subsections with lenient passes.
    using Counts = typename BodyParameters<dim>::Counts;
    std::vector<Counts>       counts(1);
    unsigned int              n_level_sets = 0;
    std::vector<unsigned int> fem_motions;
    for (unsigned int pass = 0;; ++pass)
      {
        ParameterHandler prm;
        declare_parameters(prm, counts, n_level_sets, fem_motions);
        parse_prm_file(prm, file, true);
        std::vector<Counts> found(prm.get_integer("number of bodies"));
        for (unsigned int b = 0; b < std::min(found.size(), counts.size()); ++b)
          {
            prm.enter_subsection(parameter_tools::numbered("body", b));
            found[b] = BodyParameters<dim>::parse_counts(prm);
            prm.leave_subsection();
          }
        const unsigned int level_sets =
          GridBoundaries<dim>::parse_number_of_level_sets(prm);
        std::vector<unsigned int> found_motions(prm.get_integer(
                                                  "number of FEM bodies"),
                                                1);
        for (unsigned int b = 0;
             b < std::min(found_motions.size(), fem_motions.size());
             ++b)
          {
            prm.enter_subsection(parameter_tools::numbered("fem body", b));
            found_motions[b] =
              FemBodyParameters<dim>::parse_number_of_motions(prm);
            prm.leave_subsection();
          }
        if (found == counts && level_sets == n_level_sets &&
            found_motions == fem_motions)
          break;
        counts       = found;
        n_level_sets = level_sets;
        fem_motions  = found_motions;
        AssertThrow(pass < 3, ExcInternalError());
      }

    ParameterHandler prm;
    declare_parameters(prm, counts, n_level_sets, fem_motions);
    parse_prm_file(prm, file, false);
    // An empty file would run the default body; a user who passed the
    // wrong file should hear of it instead. A scene is what the file says
    // of its bodies: at least one entry of 'body N' / 'fem body N' or a
    // body count.
    const PrmEntryOrigins origins(file);
    if (!origins.sets_any_entry())
      throw InputError(file + ": the file sets no entry; a scene needs at "
                              "least its bodies ('body 0' or 'fem body 0', "
                              "see prm/default.prm)");
    if (!origins.sets_entry("number of bodies", "body ") &&
        !origins.sets_entry("number of FEM bodies", "fem body "))
      throw InputError(file + ": the file defines no body: set the entries "
                              "of 'body 0' (its shape) or 'fem body 0', or "
                              "'number of bodies' (see prm/default.prm)");
    try
      {
        parse_parameters(prm);
      }
    catch (const InputError &error)
      {
        throw InputError(file + ": " + error.what());
      }
  }



  template struct SceneParameters<2>;
  template struct SceneParameters<3>;
} // namespace bfemp
