// Blocking reads of one message with a deadline (recv_all's waits and errors), for the readers
// that wait for an answer: the pipeserver's TileSender and the first message of the display
// stream. The header and fixed part go through MessageHead, as in every reader.
#pragma once

#include <string>
#include <string_view>

#include "base/socket.hpp"
#include "viz_link/wire.hpp"

namespace l2::viz {

// Clears `head` and receives the next header into it. A failed receive is a NetError (or
// ConnectionClosed) with " (waiting for <waiting_for>)" added when that is given; a bad header
// is "<peer>: <reason>".
void recv_header(int fd, MessageHead& head, Clock::time_point deadline, const std::string& peer,
                 std::string_view waiting_for = {});
// The fixed part after the header.
void recv_fixed(int fd, MessageHead& head, Clock::time_point deadline, const std::string& peer);
// The text of the ERROR whose header `head` holds, made printable.
std::string recv_error_text(int fd, const MessageHead& head, Clock::time_point deadline,
                            const std::string& peer);

}  // namespace l2::viz
