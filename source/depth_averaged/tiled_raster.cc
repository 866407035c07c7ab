#include <algorithm>
#include <istream>
#include <ostream>
#include <slidewave/depth_averaged/tiled_raster.h>

namespace slidewave
{
  namespace depth_averaged
  {
    TiledRaster::TiledRaster(const unsigned int         width,
                             const unsigned int         height,
                             const std::vector<double> &defaults)
      : n_columns(width)
      , n_rows(height)
      , n_tile_columns((width + tile_size - 1) / tile_size)
      , initial(defaults)
      , slot(static_cast<std::size_t>(n_tile_columns) * ((height + tile_size - 1) / tile_size), -1)
    {
    }



    void
    TiledRaster::allocate(const std::size_t t)
    {
      slot[t] = storage.size();
      storage.emplace_back(static_cast<std::size_t>(tile_size) * tile_size * initial.size());
      for (std::size_t p = 0; p < static_cast<std::size_t>(tile_size) * tile_size; ++p)
        std::copy(initial.begin(), initial.end(), storage.back().begin() + p * initial.size());
    }



    const double *
    TiledRaster::find(const unsigned int i, const unsigned int j) const
    {
      const std::size_t t
        = static_cast<std::size_t>(j / tile_size) * n_tile_columns + i / tile_size;
      if (slot[t] < 0)
        return nullptr;
      return storage[slot[t]].data()
             + ((j % tile_size) * tile_size + i % tile_size) * initial.size();
    }



    void
    TiledRaster::fill_row(const unsigned int v, const unsigned int j, double *row) const
    {
      for (unsigned int i0 = 0; i0 < n_columns; i0 += tile_size)
        {
          const unsigned int n     = std::min(tile_size, n_columns - i0);
          const double      *pixel = find(i0, j);
          for (unsigned int a = 0; a < n; ++a)
            row[i0 + a] = pixel == nullptr ? initial[v] : pixel[a * initial.size() + v];
        }
    }



    void
    TiledRaster::save(std::ostream &out) const
    {
      const std::int64_t n = storage.size();
      out.write(reinterpret_cast<const char *>(&n), sizeof(n));
      for (std::size_t t = 0; t < slot.size(); ++t)
        if (slot[t] >= 0)
          {
            const std::int64_t index = t;
            out.write(reinterpret_cast<const char *>(&index), sizeof(index));
            out.write(reinterpret_cast<const char *>(storage[slot[t]].data()),
                      static_cast<std::streamsize>(storage[slot[t]].size() * sizeof(double)));
          }
    }



    bool
    TiledRaster::load(std::istream &in)
    {
      std::fill(slot.begin(), slot.end(), -1);
      storage.clear();
      std::int64_t n = 0;
      in.read(reinterpret_cast<char *>(&n), sizeof(n));
      if (!in || n < 0 || static_cast<std::size_t>(n) > slot.size())
        return false;
      for (std::int64_t k = 0; k < n; ++k)
        {
          std::int64_t index = -1;
          in.read(reinterpret_cast<char *>(&index), sizeof(index));
          if (!in || index < 0 || static_cast<std::size_t>(index) >= slot.size()
              || slot[index] >= 0)
            return false;
          slot[index] = storage.size();
          storage.emplace_back(static_cast<std::size_t>(tile_size) * tile_size * initial.size());
          in.read(reinterpret_cast<char *>(storage.back().data()),
                  static_cast<std::streamsize>(storage.back().size() * sizeof(double)));
          if (!in)
            return false;
        }
      return true;
    }



    std::size_t
    TiledRaster::memory_consumption() const
    {
      return slot.size() * sizeof(int)
             + storage.size() * tile_size * tile_size * initial.size() * sizeof(double);
    }
  } // namespace depth_averaged
} // namespace slidewave
