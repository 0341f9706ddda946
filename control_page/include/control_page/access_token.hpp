// The run's token: whoever steers the wall (and, beyond this machine, whoever reads its page)
// shows it. Printed by l2wall in the page's URL; 128 random bits, so it cannot be guessed.
#pragma once

#include <string>
#include <string_view>

namespace l2 {

// 32 lowercase hex digits from the system's random source.
std::string make_access_token();

// Compared in time independent of where they differ, so the token cannot be found a character
// at a time by timing refusals.
bool token_matches(std::string_view given, std::string_view token);

}  // namespace l2
