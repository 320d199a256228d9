#include <boost/crc.hpp>

#include <dyncontact/base/checksum.h>

#include <fstream>
#include <sstream>
#include <vector>

namespace dyncontact
{
  std::string
  checksum_of_text(const std::string &text)
  {
    boost::crc_32_type crc;
    crc.process_bytes(text.data(), text.size());
    std::ostringstream s;
    s << std::hex << crc.checksum();
    return s.str();
  }



  std::string
  checksum_of_file(const std::string &name)
  {
    boost::crc_32_type crc;
    std::ifstream      in(name, std::ios::binary);
    std::vector<char>  buffer(1 << 20);
    while (in)
      {
        in.read(buffer.data(), buffer.size());
        crc.process_bytes(buffer.data(), in.gcount());
      }
    std::ostringstream s;
    s << std::hex << crc.checksum();
    return s.str();
  }
} // namespace dyncontact
