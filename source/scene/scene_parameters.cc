#include <bfemp/base/input_error.h>
#include <bfemp/base/parameter_tools.h>
#include <bfemp/scene/scene_parameters.h>

#include <filesystem>

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
    /** deal.II exception text without the source-location preamble. */
    std::string
    what_deal_ii_says(const std::exception &error)
    {
      const std::string text   = error.what();
      const std::string marker = "Additional information: ";
      const auto        at     = text.find(marker);
      std::string       said =
        at == std::string::npos ? text : text.substr(at + marker.size());
      const auto end = said.find("\n--------");
      if (end != std::string::npos)
        said = said.substr(0, end);
      while (!said.empty() && (said.back() == '\n' || said.back() == ' '))
        said.pop_back();
      for (auto &c : said)
        if (c == '\n')
          c = ' ';
      return said;
    }
  } // namespace



  void
  parse_prm_file(ParameterHandler  &prm,
                 const std::string &file,
                 const bool         lenient)
  {
    if (!std::filesystem::is_regular_file(file))
      throw InputError(file + ": no such parameter file");
    try
      {
        prm.parse_input(file, "", lenient);
      }
    catch (const InputError &)
      {
        throw;
      }
    catch (const std::exception &error)
      {
        throw InputError(file + ": " + what_deal_ii_says(error));
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
    ParameterHandler                &prm,
    const std::vector<unsigned int> &primitives_per_body,
    const unsigned int               n_level_sets)
  {
    declare_dimension(prm);
    prm.declare_entry("number of bodies",
                      "1",
                      Patterns::Integer(1),
                      "[-] Number of MPM bodies, subsections 'body 0', 'body "
                      "1', ...");
    RunParameters::declare_parameters(prm);
    GridParameters<dim>::declare_parameters(prm);
    TimeParameters::declare_parameters(prm);
    TransferParameters::declare_parameters(prm);
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
    for (unsigned int b = 0; b < primitives_per_body.size(); ++b)
      {
        prm.enter_subsection(parameter_tools::numbered("body", b));
        BodyParameters<dim>::declare_parameters(prm, primitives_per_body[b]);
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
    prm.enter_subsection("gravity");
    gravity = parameter_tools::get_vector<dim>(prm, "acceleration");
    prm.leave_subsection();
    boundaries.parse_parameters(prm);
    output.parse_parameters(prm);
    bodies.resize(prm.get_integer("number of bodies"));
    for (unsigned int b = 0; b < bodies.size(); ++b)
      {
        const std::string name = parameter_tools::numbered("body", b);
        prm.enter_subsection(name);
        bodies[b].parse_parameters(prm, name);
        prm.leave_subsection();
      }
  }



  template <int dim>
  void
  SceneParameters<dim>::read(const std::string &file)
  {
    // Settle the counts of numbered subsections with lenient passes.
    std::vector<unsigned int> primitives(1, 1);
    unsigned int              n_level_sets = 0;
    for (unsigned int pass = 0;; ++pass)
      {
        ParameterHandler prm;
        declare_parameters(prm, primitives, n_level_sets);
        parse_prm_file(prm, file, true);
        std::vector<unsigned int> found(prm.get_integer("number of bodies"), 1);
        for (unsigned int b = 0; b < std::min(found.size(), primitives.size()); ++b)
          {
            prm.enter_subsection(parameter_tools::numbered("body", b));
            found[b] = BodyParameters<dim>::parse_number_of_primitives(prm);
            prm.leave_subsection();
          }
        const unsigned int level_sets =
          GridBoundaries<dim>::parse_number_of_level_sets(prm);
        if (found == primitives && level_sets == n_level_sets)
          break;
        primitives   = found;
        n_level_sets = level_sets;
        AssertThrow(pass < 3, ExcInternalError());
      }

    ParameterHandler prm;
    declare_parameters(prm, primitives, n_level_sets);
    parse_prm_file(prm, file, false);
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
