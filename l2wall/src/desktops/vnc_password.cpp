// The one file that includes libvncserver's header: a password file as Xvnc and x11vnc read it.
#include <rfb/rfb.h>

#include <cstdlib>
#include <string>

namespace l2 {

// The password in `file` (`vncpasswd -f`'s obfuscated form); nullopt-like empty on failure.
bool read_vnc_password(const std::string& file, std::string& password) {
  std::string name = file;
  char* plain = rfbDecryptPasswdFromFile(name.data());
  if (!plain) return false;
  password = plain;
  std::free(plain);
  return true;
}

}  // namespace l2
