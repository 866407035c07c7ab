#ifndef slidewave_depth_averaged_tiled_raster_h
#define slidewave_depth_averaged_tiled_raster_h

#include <cstdint>
#include <iosfwd>
#include <vector>

namespace slidewave
{
  namespace depth_averaged
  {
    /**
     * A raster of width x height pixels holding a few doubles per pixel, stored in square
     * tiles of tile_size x tile_size pixels that are allocated the first time one of their
     * pixels is written. A pixel of a tile never written holds the defaults. The hazard
     * maps live on it: a landslide touches a small part of a regional DEM (issue 28: 1 % of
     * a 4-million-pixel raster), and the maps cost memory where the flow went, not over the
     * whole raster (six doubles per pixel of 4 million pixels would be 192 MB).
     *
     * Pixel (i, j) is column i, row j, counted from the lower left (y growing); its index
     * is j * width + i.
     */
    class TiledRaster
    {
    public:
      static constexpr unsigned int tile_size = 32;

      /** @p defaults: the values (one per value of a pixel) of every pixel not written. */
      TiledRaster(unsigned int width, unsigned int height, const std::vector<double> &defaults);

      unsigned int
      width() const
      {
        return n_columns;
      }

      unsigned int
      height() const
      {
        return n_rows;
      }

      /** Values per pixel. */
      unsigned int
      n_values() const
      {
        return initial.size();
      }

      /** The values of pixel (i, j), for writing (its tile is allocated if it is not). */
      double *
      at(const unsigned int i, const unsigned int j)
      {
        const std::size_t t
          = static_cast<std::size_t>(j / tile_size) * n_tile_columns + i / tile_size;
        if (slot[t] < 0)
          allocate(t);
        return storage[slot[t]].data()
               + ((j % tile_size) * tile_size + i % tile_size) * initial.size();
      }

      /** The values of pixel (i, j), or nullptr if its tile was never written. */
      const double *
      find(unsigned int i, unsigned int j) const;

      /** Value @p v of the pixels of row @p j into @p row (width() entries). */
      void
      fill_row(unsigned int v, unsigned int j, double *row) const;

      /** Calls @p f(i, j, values) for every pixel of every allocated tile (pixels of a
       *  tile outside the raster excluded), tile by tile in the order of their index. */
      template <typename Function>
      void
      for_each_allocated_pixel(const Function &f) const
      {
        for (unsigned int t = 0; t < slot.size(); ++t)
          if (slot[t] >= 0)
            {
              const unsigned int i0   = (t % n_tile_columns) * tile_size;
              const unsigned int j0   = (t / n_tile_columns) * tile_size;
              const double      *data = storage[slot[t]].data();
              for (unsigned int b = 0; b < tile_size && j0 + b < n_rows; ++b)
                for (unsigned int a = 0; a < tile_size && i0 + a < n_columns; ++a)
                  f(i0 + a, j0 + b, data + (b * tile_size + a) * initial.size());
            }
      }

      /** Tiles allocated so far. */
      unsigned int
      n_allocated_tiles() const
      {
        return storage.size();
      }

      /** Writes the allocated tiles (their number, then each tile's index and values, in
       *  the order of the indices) to @p out, in this machine's byte order. */
      void
      save(std::ostream &out) const;

      /** Replaces the tiles by those save() wrote; false if @p in is cut short or holds a
       *  tile index outside the raster. */
      bool
      load(std::istream &in);

      /** Memory of the tiles and their index [bytes]. */
      std::size_t
      memory_consumption() const;

    private:
      /** Tile @p t, its pixels at the defaults. */
      void
      allocate(std::size_t t);

      unsigned int        n_columns, n_rows, n_tile_columns;
      std::vector<double> initial;
      /** Per tile: its place in storage, -1 while unallocated. */
      std::vector<int> slot;
      /** The allocated tiles: tile_size^2 pixels of n_values() values, pixel by pixel. */
      std::vector<std::vector<double>> storage;
    };
  } // namespace depth_averaged
} // namespace slidewave

#endif
