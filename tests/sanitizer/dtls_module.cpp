// A module, loaded with dlopen, whose thread-local block each thread reaches through
// __tls_get_addr: the way Mesa's driver and its LLVM, and our image codec module, hold theirs.
extern "C" __attribute__((visibility("default"))) char* l2_dtls_touch();

namespace {
__attribute__((tls_model("global-dynamic"))) thread_local char block[40];
}  // namespace

extern "C" char* l2_dtls_touch() {
  block[0] = 1;
  return block;
}
