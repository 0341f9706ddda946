#!/usr/bin/env bash
# The router's prefetches must reach the machine code. GCC 12 once deleted every call of the
# scanner's header prefetch (a function whose only work was __builtin_prefetch in a loop): the
# scan ran nearly three times slower and no test noticed. This checks the built library: each
# named object file must contain prefetch instructions.
#
#   prefetch_emitted.sh OBJDUMP ARCHIVE OBJECT...
set -euo pipefail
objdump=$1
archive=$2
shift 2
listing=$("$objdump" -d "$archive")
status=0
for object in "$@"; do
  count=$(awk -v member="$object:" '
    $1 == member { inside = 1; next }
    /^[^ \t]+\.o:/ { inside = 0 }
    inside && /\tprefetch/ { n++ }
    END { print n + 0 }' <<<"$listing")
  if ((count == 0)); then
    echo "$object in $archive: no prefetch instruction; the compiler dropped the prefetches" \
      "(see pixel_copy::prefetch_line)"
    status=1
  else
    echo "$object: $count prefetch instructions"
  fi
done
exit $status
