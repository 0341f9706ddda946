// One pseudo-terminal pair per host, for emulation on one machine: the emulator keeps the
// master, the host (pipeserver) opens slave_path() as if it were a real serial port.
#pragma once

#include <string>

#include "sync_backchannel/serial_port.hpp"

namespace l2 {

class PtyPair {
 public:
  // posix_openpt + grantpt + unlockpt + ptsname. The line is made raw (no echo, no CR/LF
  // translation) at once, so bytes the emulator writes before the host opens its end reach the
  // host unchanged and are not echoed back to the emulator. Throws SerialError.
  static PtyPair open();

  PtyPair(PtyPair&& other) noexcept = default;
  PtyPair& operator=(PtyPair&& other) noexcept = default;
  PtyPair(const PtyPair&) = delete;
  PtyPair& operator=(const PtyPair&) = delete;
  ~PtyPair() = default;

  SerialPort& master() { return master_; }
  // For example "/dev/pts/3". A host opens it with SerialPort::open(slave_path()).
  const std::string& slave_path() const { return slave_path_; }

 private:
  PtyPair(SerialPort master, std::string slave_path, Fd slave_keeper)
      : master_(std::move(master)),
        slave_path_(std::move(slave_path)),
        keeper_(std::move(slave_keeper)) {}

  SerialPort master_;
  std::string slave_path_;
  // A slave descriptor we hold open ourselves: on Linux a master reads EIO and loses queued
  // bytes whenever no slave is open, so without it a host that reconnects would break the pair.
  Fd keeper_;
};

}  // namespace l2
