// write_pfm (pfm.hpp).
#include "pfm.hpp"

#include <bit>
#include <cstdio>

namespace embed_host {

bool write_pfm(const std::string& path, uint32_t width, uint32_t height, const std::vector<float>& rgb) {
    static_assert(std::endian::native == std::endian::little, "PFM scale -1 means little-endian floats");
    if (rgb.size() != size_t(width) * height * 3) return false;
    std::FILE* file = std::fopen(path.c_str(), "wb");
    if (!file) return false;
    bool ok = std::fprintf(file, "PF\n%u %u\n-1.0\n", width, height) > 0;
    const size_t row_floats = size_t(width) * 3;
    for (uint32_t row = height; ok && row-- > 0;) {
        ok = std::fwrite(rgb.data() + row * row_floats, sizeof(float), row_floats, file) == row_floats;
    }
    return std::fclose(file) == 0 && ok;  // fclose flushes: its failure is a write's
}

}  // namespace embed_host
