#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <deal.II/base/mpi.h>
#include <deal.II/base/point.h>
#include <deal.II/dofs/dof_tools.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <phasefield/core/file_io.h>
#include <phasefield/geometry/images.h>
#include <phasefield/geometry/shapes.h>
#include <png.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <zlib.h>

namespace PhaseField
{
  namespace Images
  {
    using namespace dealii;

    namespace
    {
      /** Largest value of a colour channel. */
      constexpr unsigned char full_channel = 255;

      /**
       * The gray pixels (RGB) of phase-field values on an n x n grid:
       * black for U <= -1 (inside), white for U >= +1.
       */
      std::vector<unsigned char>
      gray_pixels(const std::vector<double> &values, const unsigned int n)
      {
        std::vector<unsigned char> rgb(3 * n * n);
        for (unsigned int k = 0; k < n * n; ++k)
          {
            const double u = std::clamp(values[k], -1., 1.);
            rgb[3 * k] = rgb[3 * k + 1] = rgb[3 * k + 2] =
              static_cast<unsigned char>(
                std::lround(0.5 * (u + 1) * full_channel));
          }
        return rgb;
      }

      /** Draw pixel @p k red (outlines and level lines). */
      void
      mark_pixel(std::vector<unsigned char> &rgb, const unsigned int k)
      {
        rgb[3 * k]     = full_channel;
        rgb[3 * k + 1] = rgb[3 * k + 2] = 0;
      }



      /** Value standing for "no feature pixel" in the distance transform. */
      constexpr double far_away = 1e20;

      /**
       * Squared distance transform of a sampled function in 1D
       * (Felzenszwalb and Huttenlocher): d(q) = min_p (q-p)^2 + f(p).
       */
      std::vector<double>
      distance_transform_1d(const std::vector<double> &f)
      {
        const int           n = f.size();
        std::vector<double> d(n), z(n + 1);
        std::vector<int>    v(n);
        int                 k   = 0;
        v[0]                    = 0;
        z[0]                    = -std::numeric_limits<double>::infinity();
        z[1]                    = std::numeric_limits<double>::infinity();
        const auto intersection = [&](const int q, const int p) {
          return ((f[q] + double(q) * q) - (f[p] + double(p) * p)) /
                 (2. * q - 2. * p);
        };
        for (int q = 1; q < n; ++q)
          {
            double s = intersection(q, v[k]);
            while (s <= z[k])
              {
                --k;
                s = intersection(q, v[k]);
              }
            ++k;
            v[k]     = q;
            z[k]     = s;
            z[k + 1] = std::numeric_limits<double>::infinity();
          }
        k = 0;
        for (int q = 0; q < n; ++q)
          {
            while (z[k + 1] < q)
              ++k;
            d[q] = double(q - v[k]) * (q - v[k]) + f[v[k]];
          }
        return d;
      }

      /**
       * Euclidean distance (in pixels) of every pixel to the nearest pixel
       * with feature[i] == true.
       */
      std::vector<double>
      distance_transform(const std::vector<bool> &feature,
                         const unsigned int       nx,
                         const unsigned int       ny)
      {
        std::vector<double> d(nx * ny);
        for (unsigned int i = 0; i < nx * ny; ++i)
          d[i] = feature[i] ? 0. : far_away;
        std::vector<double> line;
        for (unsigned int x = 0; x < nx; ++x)
          {
            line.resize(ny);
            for (unsigned int y = 0; y < ny; ++y)
              line[y] = d[y * nx + x];
            line = distance_transform_1d(line);
            for (unsigned int y = 0; y < ny; ++y)
              d[y * nx + x] = line[y];
          }
        for (unsigned int y = 0; y < ny; ++y)
          {
            line.assign(d.begin() + y * nx, d.begin() + (y + 1) * nx);
            line = distance_transform_1d(line);
            std::copy(line.begin(), line.end(), d.begin() + y * nx);
          }
        for (double &x : d)
          x = std::sqrt(x);
        return d;
      }

      /** CRC-32 of PNG chunks (ISO 3309, as in the PNG specification). */
      std::uint32_t
      png_crc(const std::string &bytes)
      {
        constexpr std::uint32_t polynomial = 0xedb88320u;
        std::uint32_t           crc        = 0xffffffffu;
        for (const unsigned char byte : bytes)
          {
            crc ^= byte;
            for (int bit = 0; bit < 8; ++bit)
              crc = (crc >> 1) ^ (polynomial & (0u - (crc & 1u)));
          }
        return crc ^ 0xffffffffu;
      }

      /**
       * True if every chunk of the PNG file @p filename is complete and
       * has the right CRC, and the file ends with IEND after an IDAT
       * chunk. VTK's reader crashes on some corrupt files, so they are
       * rejected before it sees them.
       */
      bool
      png_chunks_intact(const std::string &filename)
      {
        constexpr std::size_t signature_size = 8;
        std::ifstream         file(filename, std::ios::binary);
        const std::string     data((std::istreambuf_iterator<char>(file)),
                               std::istreambuf_iterator<char>());
        const auto            read_uint32 = [&](const std::size_t at) {
          std::uint32_t value = 0;
          for (std::size_t i = 0; i < 4; ++i)
            value = (value << 8) | static_cast<unsigned char>(data[at + i]);
          return value;
        };
        bool        has_data = false;
        std::size_t at       = signature_size;
        while (at + 12 <= data.size())
          {
            const std::size_t length = read_uint32(at);
            if (length > data.size() - at - 12)
              return false;
            const std::string type_and_data = data.substr(at + 4, length + 4);
            if (png_crc(type_and_data) != read_uint32(at + 8 + length))
              return false;
            const std::string type = type_and_data.substr(0, 4);
            has_data               = has_data || type == "IDAT";
            if (type == "IEND")
              return has_data;
            at += length + 12;
          }
        return false;
      }

      /** The big-endian 32-bit number at @p at of @p data. */
      std::uint32_t
      big_endian_uint32(const std::string &data, const std::size_t at)
      {
        std::uint32_t value = 0;
        for (std::size_t i = 0; i < 4; ++i)
          value = (value << 8) | static_cast<unsigned char>(data[at + i]);
        return value;
      }

      /** What the IHDR chunk of a PNG file says. */
      struct PngHeader
      {
        std::uint64_t width = 0, height = 0;
        /** Bits per pixel (channels times bit depth). */
        unsigned int bits_per_pixel = 0;
        bool         interlaced     = false;
      };

      /**
       * The header of the PNG file contents @p data (whose chunks are
       * intact), and the concatenated data of its IDAT chunks in
       * @p compressed; a header that is not a valid IHDR chunk is damage
       * (@p file: the start of the message).
       */
      PngHeader
      png_header(const std::string &data,
                 std::string       &compressed,
                 const std::string &file)
      {
        constexpr std::size_t ihdr_at = 8;
        if (data.size() < ihdr_at + 25 ||
            big_endian_uint32(data, ihdr_at) != 13 ||
            data.compare(ihdr_at + 4, 4, "IHDR") != 0)
          throw InputError(file + " is a damaged PNG image (no valid "
                                  "IHDR header).");
        PngHeader          header;
        const std::size_t  at        = ihdr_at + 8;
        const unsigned int bit_depth = static_cast<unsigned char>(data[at + 8]);
        const unsigned int color_type =
          static_cast<unsigned char>(data[at + 9]);
        // channels per color type 0 (gray), 2 (RGB), 3 (palette),
        // 4 (gray + alpha), 6 (RGBA)
        const unsigned int channels[7] = {1, 0, 3, 1, 2, 0, 4};
        header.width                   = big_endian_uint32(data, at);
        header.height                  = big_endian_uint32(data, at + 4);
        header.interlaced = static_cast<unsigned char>(data[at + 12]) != 0;
        if (color_type > 6 || channels[color_type] == 0 || bit_depth == 0 ||
            bit_depth > 16 || header.width == 0 || header.height == 0)
          throw InputError(file + " is a damaged PNG image (its IHDR header "
                                  "is not valid).");
        header.bits_per_pixel = channels[color_type] * bit_depth;
        for (std::size_t c = ihdr_at; c + 12 <= data.size();)
          {
            const std::size_t length = big_endian_uint32(data, c);
            if (length > data.size() - c - 12 ||
                data.compare(c + 4, 4, "IEND") == 0)
              break;
            if (data.compare(c + 4, 4, "IDAT") == 0)
              compressed += data.substr(c + 8, length);
            c += length + 12;
          }
        return header;
      }

      /**
       * The number of bytes of the decompressed image data that @p header
       * asks for: per row a filter byte and the pixels, in the seven
       * passes of Adam7 if interlaced.
       */
      std::uint64_t
      png_data_size(const PngHeader &header)
      {
        const auto rows = [&](const std::uint64_t w, const std::uint64_t h) {
          return w == 0 ? 0 : h * (1 + (w * header.bits_per_pixel + 7) / 8);
        };
        if (!header.interlaced)
          return rows(header.width, header.height);
        // Adam7: start and step of x and y in each pass
        const unsigned int x0[7] = {0, 4, 0, 2, 0, 1, 0};
        const unsigned int dx[7] = {8, 8, 4, 4, 2, 2, 1};
        const unsigned int y0[7] = {0, 0, 4, 0, 2, 0, 1};
        const unsigned int dy[7] = {8, 8, 8, 4, 4, 2, 2};
        std::uint64_t      size  = 0;
        for (unsigned int p = 0; p < 7; ++p)
          size += rows((header.width + dx[p] - 1 - x0[p]) / dx[p],
                       (header.height + dy[p] - 1 - y0[p]) / dy[p]);
        return size;
      }

      /**
       * The number of bytes that the zlib stream @p compressed inflates
       * to, at most @p limit + 1 (decompressed in pieces and discarded);
       * -1 if the stream is damaged.
       */
      long long
      inflated_size(const std::string &compressed, const std::uint64_t limit)
      {
        z_stream stream = {};
        if (inflateInit(&stream) != Z_OK)
          return -1;
        std::vector<unsigned char> buffer(1 << 16);
        stream.next_in =
          reinterpret_cast<Bytef *>(const_cast<char *>(compressed.data()));
        stream.avail_in      = compressed.size();
        std::uint64_t total  = 0;
        int           result = Z_OK;
        while (result == Z_OK && total <= limit)
          {
            stream.next_out  = buffer.data();
            stream.avail_out = buffer.size();
            result           = inflate(&stream, Z_NO_FLUSH);
            total += buffer.size() - stream.avail_out;
            if (result == Z_BUF_ERROR && stream.avail_in == 0)
              break;
          }
        inflateEnd(&stream);
        if (result != Z_OK && result != Z_STREAM_END && result != Z_BUF_ERROR)
          return -1;
        return static_cast<long long>(total);
      }

      /**
       * Check the size of the PNG file @p filename (whose chunks are
       * intact) before VTK's reader sees it: at most max_image_pixels
       * pixels, and data for every row its header claims (VTK's reader
       * crashes on missing rows). Throws InputError starting with
       * @p file otherwise.
       */
      void
      check_png_size(const std::string &filename, const std::string &file)
      {
        std::ifstream     in(filename, std::ios::binary);
        const std::string data((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        std::string       compressed;
        const PngHeader   header = png_header(data, compressed, file);
        if (header.width * header.height > max_image_pixels)
          throw InputError(
            file + " has " + std::to_string(header.width) + " x " +
            std::to_string(header.height) + " pixels, more than the limit of " +
            std::to_string(max_image_pixels) + " pixels: use a smaller image.");
        const std::uint64_t needed = png_data_size(header);
        const long long     found  = inflated_size(compressed, needed);
        if (found < 0)
          throw InputError(file + " is a damaged PNG image: its compressed "
                                  "data cannot be decoded.");
        if (static_cast<std::uint64_t>(found) < needed)
          throw InputError(
            file + " is a damaged PNG image: its header claims " +
            std::to_string(header.width) + " x " +
            std::to_string(header.height) + " pixels (" +
            std::to_string(needed) + " bytes of data), but its data holds " +
            std::to_string(found) + " bytes.");
      }

      /** The libpng structures of one read, freed at the end. */
      struct LibpngRead
      {
        png_structp png  = nullptr;
        png_infop   info = nullptr;
        std::FILE  *file = nullptr;

        ~LibpngRead()
        {
          if (png != nullptr)
            png_destroy_read_struct(&png,
                                    info != nullptr ? &info : nullptr,
                                    nullptr);
          if (file != nullptr)
            std::fclose(file);
        }
      };

      /** libpng's error function: keep the message, return to the read. */
      void
      keep_libpng_error(png_structp png, png_const_charp message)
      {
        *static_cast<std::string *>(png_get_error_ptr(png)) = message;
        png_longjmp(png, 1);
      }

      /** libpng's warning function: warnings are not printed. */
      void
      ignore_libpng_warning(png_structp, png_const_charp)
      {}

      /**
       * Decode the PNG file @p filename with libpng, the library VTK's
       * reader uses, row by row into the buffer of one row (whatever its
       * size, the image takes no more memory than that): libpng's message
       * if it finds the file damaged (a bad filter value, a palette image
       * without palette, an invalid bit depth, an unknown critical chunk,
       * ...), empty otherwise. libpng prints nothing: VTK's reader crashes
       * on such files and only libpng's line would be left.
       */
      std::string
      libpng_decode_error(const std::string &filename)
      {
        std::string           message;
        LibpngRead            read;
        std::vector<png_byte> row;
        read.file = std::fopen(filename.c_str(), "rb");
        if (read.file == nullptr)
          return std::strerror(errno);
        read.png = png_create_read_struct(PNG_LIBPNG_VER_STRING,
                                          &message,
                                          keep_libpng_error,
                                          ignore_libpng_warning);
        if (read.png != nullptr)
          read.info = png_create_info_struct(read.png);
        if (read.info == nullptr)
          return "libpng could not start reading it";
        // libpng returns here when it finds an error (keep_libpng_error())
        if (setjmp(png_jmpbuf(read.png)))
          return message.empty() ? "libpng cannot decode it" : message;
        png_init_io(read.png, read.file);
        png_read_info(read.png, read.info);
        const int n_passes = png_set_interlace_handling(read.png);
        png_read_update_info(read.png, read.info);
        row.resize(png_get_rowbytes(read.png, read.info));
        const png_uint_32 height = png_get_image_height(read.png, read.info);
        for (int pass = 0; pass < n_passes; ++pass)
          for (png_uint_32 y = 0; y < height; ++y)
            png_read_row(read.png, row.data(), nullptr);
        png_read_end(read.png, nullptr);
        return "";
      }



      /** Two sizes from `Geometry / Sizes` for @p shape. */
      std::vector<double>
      two_sizes(const GeometryParameters &geometry, const std::string &shape)
      {
        if (geometry.sizes.size() != 2)
          throw InputError("Shape <" + shape +
                           "> needs <Geometry / Sizes> = length, width.");
        return geometry.sizes;
      }
    } // namespace



    double
    box_distance(const Point<2>            &p,
                 const std::vector<double> &lower,
                 const std::vector<double> &upper)
    {
      const Point<2> center(0.5 * (lower[0] + upper[0]),
                            0.5 * (lower[1] + upper[1]));
      return Shapes::box_distance<2>(p - center,
                                     {0.5 * (upper[0] - lower[0]),
                                      0.5 * (upper[1] - lower[1])});
    }



    GrayImage
    read_gray_image(const std::string &filename,
                    const std::string &parameter_name)
    {
      const std::string file =
        "The image file <" + filename + "> given in <" + parameter_name + ">";
      std::error_code error;
      if (!std::filesystem::exists(filename, error))
        throw InputError(file + " does not exist.");
      if (!std::filesystem::is_regular_file(filename, error))
        throw InputError(file + " is not a regular file (a directory, a "
                                "device or a pipe?).");
      vtkNew<vtkPNGReader> reader;
      if (reader->CanReadFile(filename.c_str()) == 0)
        throw InputError(file + " is not a readable PNG image.");
      if (!png_chunks_intact(filename))
        throw InputError(file + " is a damaged PNG image (truncated, or a "
                                "chunk with a wrong checksum).");
      check_png_size(filename, file);
      const std::string decode_error = libpng_decode_error(filename);
      if (!decode_error.empty())
        throw InputError(file + " is a damaged PNG image: " + decode_error +
                         " (libpng).");
      reader->SetFileName(filename.c_str());
      // VTK reports corrupt data through its error events, not exceptions
      bool                       read_error = false;
      vtkNew<vtkCallbackCommand> error_observer;
      error_observer->SetClientData(&read_error);
      error_observer->SetCallback(
        [](vtkObject *, unsigned long, void *client_data, void *) {
          *static_cast<bool *>(client_data) = true;
        });
      reader->AddObserver(vtkCommand::ErrorEvent, error_observer);
      reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent,
                                          error_observer);
      reader->Update();
      vtkImageData *image = reader->GetOutput();
      if (read_error || reader->GetErrorCode() != 0)
        throw InputError(file + " is a damaged PNG image: its data could not "
                                "be decoded.");
      int dims[3];
      image->GetDimensions(dims);
      if (dims[0] < 1 || dims[1] < 1)
        throw InputError(file + " has no pixels.");
      GrayImage result;
      result.nx              = dims[0];
      result.ny              = dims[1];
      const int n_components = image->GetNumberOfScalarComponents();
      // gray (+ alpha): the gray value; RGB (+ alpha): the mean of RGB
      const int    n_color       = n_components <= 2 ? 1 : 3;
      const double maximum_value = image->GetScalarTypeMax();
      // VTK's image rows run from the bottom, like y
      result.gray.resize(result.nx * result.ny);
      for (unsigned int y = 0; y < result.ny; ++y)
        for (unsigned int x = 0; x < result.nx; ++x)
          {
            double gray = 0;
            for (int c = 0; c < n_color; ++c)
              gray += image->GetScalarComponentAsDouble(x, y, 0, c);
            result.gray[y * result.nx + x] = gray / (n_color * maximum_value);
          }
      return result;
    }



    ImageDistance::ImageDistance(const std::string &filename,
                                 const double       threshold)
    {
      const GrayImage image =
        read_gray_image(filename, "Geometry / Image file");
      if (image.nx < 2 || image.ny < 2)
        throw InputError("The image file <" + filename +
                         "> given in <Geometry / Image file> has fewer than "
                         "2 x 2 pixels.");
      nx         = image.nx;
      ny         = image.ny;
      pixel_size = 1. / std::max(nx, ny);
      std::vector<bool> inside(nx * ny), outside(nx * ny);
      unsigned int      n_inside = 0;
      for (unsigned int i = 0; i < nx * ny; ++i)
        {
          inside[i]  = image.gray[i] < threshold;
          outside[i] = !inside[i];
          n_inside += inside[i];
        }
      if (n_inside == 0 || n_inside == nx * ny)
        throw InputError(
          "The image file <" + filename + "> has " +
          (n_inside == 0 ? "no pixel darker" : "no pixel lighter") +
          " than <Geometry / Threshold>: there is no edge.");

      // the edge lies half-way between an inside and an outside pixel
      const std::vector<double> to_inside = distance_transform(inside, nx, ny);
      const std::vector<double> to_outside =
        distance_transform(outside, nx, ny);
      distance.resize(nx * ny);
      for (unsigned int i = 0; i < nx * ny; ++i)
        distance[i] = pixel_size *
                      (inside[i] ? -(to_outside[i] - 0.5) : to_inside[i] - 0.5);
    }



    double
    ImageDistance::value(const Point<2> &p, const unsigned int) const
    {
      // bilinear interpolation between pixel centres, clamped at the border
      const auto coordinate = [&](const double x, const unsigned int n) {
        const double       s = std::clamp(x / pixel_size - 0.5, 0., n - 1.);
        const unsigned int i = std::min<unsigned int>(s, n - 2);
        return std::make_pair(i, s - i);
      };
      const auto [i, sx] = coordinate(p[0], nx);
      const auto [j, sy] = coordinate(p[1], ny);
      const auto d       = [&](const unsigned int x, const unsigned int y) {
        return distance[y * nx + x];
      };
      return (1 - sy) * ((1 - sx) * d(i, j) + sx * d(i + 1, j)) +
             sy * ((1 - sx) * d(i, j + 1) + sx * d(i + 1, j + 1));
    }



    std::shared_ptr<Function<2>>
    create_damaged_image(const GeometryParameters &geometry,
                         const std::string        &image_file,
                         const double              threshold,
                         const Box2D              &damage)
    {
      const std::string           &shape  = geometry.shape;
      const Point<2>               center = Shapes::shape_center<2>(geometry);
      std::shared_ptr<Function<2>> intact;
      if (shape == "damaged circle")
        {
          if (!(geometry.radius > 0))
            throw InputError("<Geometry / Radius> must be positive.");
          intact = std::make_shared<Shapes::SphereDistance<2>>(center,
                                                               geometry.radius);
        }
      else if (shape == "cross" || shape == "bar")
        {
          const std::vector<double> sizes = two_sizes(geometry, shape);
          const std::vector<double> lower = {center[0] - sizes[0] / 2,
                                             center[1] - sizes[1] / 2};
          const std::vector<double> upper = {center[0] + sizes[0] / 2,
                                             center[1] + sizes[1] / 2};
          // the cross: the bar and the bar rotated by 90 degrees
          const std::vector<double> lower_rotated = {center[0] - sizes[1] / 2,
                                                     center[1] - sizes[0] / 2};
          const std::vector<double> upper_rotated = {center[0] + sizes[1] / 2,
                                                     center[1] + sizes[0] / 2};
          const bool                is_cross      = (shape == "cross");
          intact = std::make_shared<Shapes::FunctionFromCallable<2>>(
            [=](const Point<2> &p) {
              const double bar = box_distance(p, lower, upper);
              return is_cross ?
                       std::min(bar,
                                box_distance(p, lower_rotated, upper_rotated)) :
                       bar;
            });
        }
      else if (shape == "image")
        intact = std::make_shared<ImageDistance>(image_file, threshold);
      else
        intact = Shapes::create_signed_distance<2>(geometry);

      if (damage.empty())
        return intact;
      // the shape minus the damaged box
      return std::make_shared<Shapes::FunctionFromCallable<2>>(
        [intact, damage](const Point<2> &p) {
          return std::max(intact->value(p),
                          -box_distance(p, damage.lower, damage.upper));
        });
    }



    void
    write_picture(const std::vector<double> &values,
                  const unsigned int         n,
                  const Box2D               &region,
                  const std::string         &filename)
    {
      constexpr double outline_width = 1.5; // pixels
      const auto       near          = [&](const double pixel, const double x) {
        return std::abs(pixel - (x * n - 0.5)) <= outline_width / 2;
      };
      const auto between =
        [&](const double pixel, const double a, const double b) {
          return pixel >= a * n - 0.5 - outline_width / 2 &&
                 pixel <= b * n - 0.5 + outline_width / 2;
        };
      std::vector<unsigned char> rgb = gray_pixels(values, n);
      for (unsigned int y = 0; y < n; ++y)
        for (unsigned int x = 0; x < n; ++x)
          if (((near(x, region.lower[0]) || near(x, region.upper[0])) &&
               between(y, region.lower[1], region.upper[1])) ||
              ((near(y, region.lower[1]) || near(y, region.upper[1])) &&
               between(x, region.lower[0], region.upper[0])))
            mark_pixel(rgb, y * n + x);
      write_rgb_png(rgb, n, n, filename);
    }



    void
    write_picture_with_zero_contour(const std::vector<double> &values,
                                    const unsigned int         n,
                                    const std::string         &filename)
    {
      AssertDimension(values.size(), n * n);
      std::vector<unsigned char> rgb = gray_pixels(values, n);
      // of two neighbours of opposite signs, the one nearer to zero
      const auto crossing = [&](const unsigned int a, const unsigned int b) {
        if (values[a] * values[b] < 0 || (values[a] == 0) != (values[b] == 0))
          mark_pixel(rgb, std::abs(values[a]) <= std::abs(values[b]) ? a : b);
      };
      for (unsigned int y = 0; y < n; ++y)
        for (unsigned int x = 0; x < n; ++x)
          {
            if (x + 1 < n)
              crossing(y * n + x, y * n + x + 1);
            if (y + 1 < n)
              crossing(y * n + x, (y + 1) * n + x);
          }
      write_rgb_png(rgb, n, n, filename);
    }



    void
    write_rgb_png(const std::vector<unsigned char> &rgb,
                  const unsigned int                nx,
                  const unsigned int                ny,
                  const std::string                &filename)
    {
      AssertDimension(rgb.size(), 3 * nx * ny);
      vtkNew<vtkImageData> image;
      image->SetDimensions(nx, ny, 1);
      image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
      std::copy(rgb.begin(),
                rgb.end(),
                static_cast<unsigned char *>(image->GetScalarPointer()));
      vtkNew<vtkPNGWriter> writer;
      writer->SetFileName(filename.c_str());
      writer->SetInputData(image);
      errno = 0;
      writer->Write();
      const int error = errno;
      // VTK does not report every failed write (a full disk): the file
      // must be a complete PNG image
      if (writer->GetErrorCode() != 0 || !png_chunks_intact(filename))
        throw WriteError(write_failure_message(filename, error));
    }



    std::vector<double>
    sample_on_pixel_grid(const DoFHandler<2> &dof_handler,
                         const Vector        &u,
                         const unsigned int   n)
    {
      IndexSet relevant;
      DoFTools::extract_locally_relevant_dofs(dof_handler, relevant);
      Vector ghosted(dof_handler.locally_owned_dofs(),
                     relevant,
                     u.get_mpi_communicator());
      ghosted = u;

      // every pixel centre lies in exactly one half-open cell [x0,x1)x[y0,y1)
      std::vector<double> values(n * n, 0.);
      const auto          first_pixel = [n](const double x) {
        return static_cast<int>(std::ceil(x * n - 0.5));
      };
      for (const auto &cell : dof_handler.active_cell_iterators())
        if (cell->is_locally_owned())
          {
            // Q1 vertices 0..3: (0,0), (1,0), (0,1), (1,1) of the cell
            const Point<2> lower = cell->vertex(0), upper = cell->vertex(3);
            const double   width = upper[0] - lower[0];
            double         corner[4];
            for (unsigned int v = 0; v < 4; ++v)
              corner[v] = ghosted(cell->vertex_dof_index(v, 0));
            for (int j = std::max(0, first_pixel(lower[1]));
                 j < std::min<int>(n, first_pixel(upper[1]));
                 ++j)
              for (int i = std::max(0, first_pixel(lower[0]));
                   i < std::min<int>(n, first_pixel(upper[0]));
                   ++i)
                {
                  const double sx = ((i + 0.5) / n - lower[0]) / width;
                  const double sy = ((j + 0.5) / n - lower[1]) / width;
                  values[j * n + i] =
                    (1 - sy) * ((1 - sx) * corner[0] + sx * corner[1]) +
                    sy * ((1 - sx) * corner[2] + sx * corner[3]);
                }
          }
      Utilities::MPI::sum(values, u.get_mpi_communicator(), values);
      return values;
    }
  } // namespace Images
} // namespace PhaseField
