#include <dyncontact/base/checksum.h>

#include <zlib.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <vector>

namespace dyncontact
{
  namespace
  {
    /// zlib's CRC-32 of @p size bytes at @p data after @p crc, in pieces
    /// that its unsigned int size takes.
    unsigned long
    crc_of(unsigned long crc, const char *data, std::size_t size)
    {
      while (size > 0)
        {
          const uInt piece =
            static_cast<uInt>(std::min<std::size_t>(size, 1u << 30));
          crc = crc32(crc, reinterpret_cast<const Bytef *>(data), piece);
          data += piece;
          size -= piece;
        }
      return crc;
    }

    std::string
    hexadecimal(const unsigned long crc)
    {
      std::ostringstream s;
      s << std::hex << crc;
      return s.str();
    }
  } // namespace



  std::string
  checksum_of_text(const std::string &text)
  {
    return hexadecimal(crc_of(crc32(0L, Z_NULL, 0), text.data(), text.size()));
  }



  std::string
  checksum_of_file(const std::string &name)
  {
    unsigned long     crc = crc32(0L, Z_NULL, 0);
    std::ifstream     in(name, std::ios::binary);
    std::vector<char> buffer(1 << 20);
    while (in)
      {
        in.read(buffer.data(), buffer.size());
        crc = crc_of(crc, buffer.data(), in.gcount());
      }
    return hexadecimal(crc);
  }
} // namespace dyncontact
