#include <bfemp/base/input_error.h>
#include <bfemp/particles/voxel_image.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace bfemp
{
  namespace
  {
    [[noreturn]] void
    fail(const std::string &file, const std::string &what)
    {
      throw InputError("voxel image '" + file + "': " + what);
    }

    /** Bytes of one value of a VTK scalar type, 0 if unsupported. */
    unsigned int
    type_size(const std::string &type)
    {
      static const std::map<std::string, unsigned int> sizes = {
        {"unsigned_char", 1},
        {"char", 1},
        {"unsigned_short", 2},
        {"short", 2},
        {"unsigned_int", 4},
        {"int", 4},
        {"float", 4},
        {"double", 8}};
      const auto entry = sizes.find(type);
      return entry == sizes.end() ? 0 : entry->second;
    }

    /** One big-endian value of a VTK type (legacy binary files are
     *  big-endian whatever machine wrote them). */
    double
    big_endian_value(const unsigned char *bytes, const std::string &type)
    {
      unsigned char      swapped[8];
      const unsigned int size = type_size(type);
      for (unsigned int b = 0; b < size; ++b)
        swapped[b] = bytes[size - 1 - b];
      if (type == "unsigned_char")
        return bytes[0];
      if (type == "char")
        return static_cast<signed char>(bytes[0]);
      if (type == "unsigned_short")
        return (bytes[0] << 8) | bytes[1];
      if (type == "short")
        return static_cast<std::int16_t>((bytes[0] << 8) | bytes[1]);
      if (type == "unsigned_int" || type == "int")
        {
          std::uint32_t v = 0;
          for (unsigned int b = 0; b < 4; ++b)
            v = (v << 8) | bytes[b];
          return type == "int"
                   ? static_cast<double>(static_cast<std::int32_t>(v))
                   : static_cast<double>(v);
        }
      if (type == "float")
        {
          float v;
          std::memcpy(&v, swapped, 4);
          return v;
        }
      double v;
      std::memcpy(&v, swapped, 8);
      return v;
    }
  } // namespace



  template <int dim>
  VoxelImage<dim>
  VoxelImage<dim>::read(const std::string                   &file,
                        const std::array<unsigned int, dim> &raw_size,
                        const Point<dim>                    &raw_origin,
                        const Point<dim>                    &raw_spacing)
  {
    if (!std::filesystem::is_regular_file(file))
      fail(file, "no such file");
    const std::string extension = std::filesystem::path(file).extension();
    if (extension == ".vtk")
      return read_vtk(file);
    if (extension == ".raw")
      return read_raw(file, raw_size, raw_origin, raw_spacing);
    fail(file,
         "must end in .vtk (legacy VTK STRUCTURED_POINTS) or .raw (unsigned "
         "8-bit values)");
  }



  template <int dim>
  VoxelImage<dim>
  VoxelImage<dim>::read_vtk(const std::string &file)
  {
    std::ifstream in(file, std::ios::binary);
    std::string   line;
    std::getline(in, line);
    if (line.rfind("# vtk DataFile", 0) != 0)
      fail(file, "not a legacy VTK file (no '# vtk DataFile' header)");
    std::getline(in, line); // title
    std::string format;
    in >> format;
    if (format != "ASCII" && format != "BINARY")
      fail(file,
           "the third line must be ASCII or BINARY, not '" + format + "'");
    std::string keyword, dataset;
    in >> keyword >> dataset;
    if (keyword != "DATASET" || dataset != "STRUCTURED_POINTS")
      fail(file,
           "only DATASET STRUCTURED_POINTS is read (a regular image), not '" +
             keyword + " " + dataset + "'");

    std::array<unsigned int, 3> dims      = {{0, 0, 0}};
    std::array<double, 3>       origin3   = {{0., 0., 0.}};
    std::array<double, 3>       spacing3  = {{1., 1., 1.}};
    bool                        cell_data = false;
    std::string                 type;
    while (in >> keyword)
      {
        if (keyword == "DIMENSIONS")
          in >> dims[0] >> dims[1] >> dims[2];
        else if (keyword == "ORIGIN")
          in >> origin3[0] >> origin3[1] >> origin3[2];
        else if (keyword == "SPACING" || keyword == "ASPECT_RATIO")
          in >> spacing3[0] >> spacing3[1] >> spacing3[2];
        else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
          {
            cell_data = keyword == "CELL_DATA";
            std::size_t count;
            in >> count;
          }
        else if (keyword == "SCALARS")
          {
            std::string name;
            in >> name >> type;
            std::getline(in, line); // optional component count
            std::istringstream rest(line);
            unsigned int       components = 1;
            rest >> components;
            if (components != 1)
              fail(file, "SCALARS must have one component");
          }
        else if (keyword == "LOOKUP_TABLE")
          {
            std::getline(in, line); // its name; the data follow
            break;
          }
        else
          fail(file, "unexpected keyword '" + keyword + "' in the header");
        if (!in)
          fail(file, "malformed '" + keyword + "' line");
      }
    if (type.empty() || type_size(type) == 0)
      fail(file,
           "needs a SCALARS line of type unsigned_char, char, "
           "unsigned_short, short, unsigned_int, int, float or double (read '" +
             type + "') followed by LOOKUP_TABLE");

    VoxelImage image;
    for (unsigned int d = 0; d < 3; ++d)
      if (dims[d] == 0 || (cell_data && dims[d] < 2 && d < dim))
        fail(file, "DIMENSIONS must be positive (cell data: at least 2)");
    for (unsigned int d = dim; d < 3; ++d)
      if (dims[d] != 1)
        fail(file,
             "a " + std::to_string(dim) + "D scene needs an image with " +
               (dim == 2 ? "one layer (DIMENSIONS nx ny 1)" : "3 dimensions"));
    std::size_t total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (!(spacing3[d] > 0.))
          fail(file, "SPACING must be > 0 in every direction");
        // cell data: the samples are the cells, centred half a spacing in
        image.n[d]       = cell_data ? dims[d] - 1 : dims[d];
        image.spacing[d] = spacing3[d];
        image.origin[d]  = origin3[d] + (cell_data ? 0.5 * spacing3[d] : 0.);
        total *= image.n[d];
      }

    image.values.resize(total);
    if (format == "ASCII")
      {
        for (double &v : image.values)
          if (!(in >> v))
            fail(file,
                 "holds fewer than the " + std::to_string(total) +
                   " values its DIMENSIONS announce");
      }
    else
      {
        const unsigned int         size = type_size(type);
        std::vector<unsigned char> bytes(total * size);
        in.read(reinterpret_cast<char *>(bytes.data()), bytes.size());
        if (static_cast<std::size_t>(in.gcount()) != bytes.size())
          fail(file,
               "holds fewer than the " + std::to_string(total) +
                 " binary values its DIMENSIONS announce");
        for (std::size_t i = 0; i < total; ++i)
          image.values[i] = big_endian_value(&bytes[i * size], type);
      }
    for (const double v : image.values)
      if (!std::isfinite(v))
        fail(file, "holds a value that is not finite");
    return image;
  }



  template <int dim>
  VoxelImage<dim>
  VoxelImage<dim>::read_raw(const std::string                   &file,
                            const std::array<unsigned int, dim> &size,
                            const Point<dim>                    &origin,
                            const Point<dim>                    &spacing)
  {
    VoxelImage  image;
    std::size_t total = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        if (size[d] == 0 || !(spacing[d] > 0.))
          fail(file,
               "a raw image needs 'image size' >= 1 and 'image spacing' > 0 "
               "in every direction");
        total *= size[d];
      }
    image.n              = size;
    image.origin         = origin;
    image.spacing        = spacing;
    const auto file_size = std::filesystem::file_size(file);
    if (file_size != total)
      fail(file,
           "has " + std::to_string(file_size) + " bytes, but 'image size' " +
             "announces " + std::to_string(total) +
             " unsigned 8-bit values (x fastest)");
    std::ifstream              in(file, std::ios::binary);
    std::vector<unsigned char> bytes(total);
    in.read(reinterpret_cast<char *>(bytes.data()), bytes.size());
    image.values.assign(bytes.begin(), bytes.end());
    return image;
  }



  template <int dim>
  double
  VoxelImage<dim>::value(const Point<dim> &x) const
  {
    std::size_t index = 0, stride = 1;
    for (unsigned int d = 0; d < dim; ++d)
      {
        const double i = std::floor((x[d] - origin[d]) / spacing[d] + 0.5);
        if (i < 0. || i >= n[d])
          return std::numeric_limits<double>::quiet_NaN();
        index += static_cast<std::size_t>(i) * stride;
        stride *= n[d];
      }
    return values[index];
  }



  template <int dim>
  BoundingBox<dim>
  VoxelImage<dim>::bounding_box() const
  {
    Point<dim> lower, upper;
    for (unsigned int d = 0; d < dim; ++d)
      {
        lower[d] = origin[d] - 0.5 * spacing[d];
        upper[d] = origin[d] + (n[d] - 0.5) * spacing[d];
      }
    return BoundingBox<dim>(std::make_pair(lower, upper));
  }



  template <int dim>
  const std::array<unsigned int, dim> &
  VoxelImage<dim>::size() const
  {
    return n;
  }



  template class VoxelImage<2>;
  template class VoxelImage<3>;
} // namespace bfemp
