#ifndef dyncontact_base_checksum_h
#define dyncontact_base_checksum_h

#include <string>

namespace dyncontact
{
  /// The CRC-32 of the bytes of @p text, as a hexadecimal string.
  std::string
  checksum_of_text(const std::string &text);

  /// The CRC-32 of the file @p name, as a hexadecimal string (that of no
  /// bytes if the file cannot be read).
  std::string
  checksum_of_file(const std::string &name);
} // namespace dyncontact

#endif
