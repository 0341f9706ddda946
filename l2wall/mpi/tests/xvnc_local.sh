# xvnc_local OUT: a private desktop for the MPI tests of vnc content, started in the background:
# TigerVNC's Xvnc at the default wall's canvas size (1300x980), RFB on 127.0.0.1 only at port
# 5900 + the display number it picks itself (-displayfd, so two at once never meet), no
# password, showing a still two-colour pattern. Sets `xvnc` (its pid, for the caller's trap)
# and `display` (its number); its log is OUT/xvnc.log. Sourced by the MPI test scripts.
xvnc_local() {
  local out=$1
  Xvnc -displayfd 3 -geometry 1300x980 -depth 24 -interface 127.0.0.1 -nolisten tcp \
    -SecurityTypes None 3>"$out/display" 2>"$out/xvnc.log" &
  xvnc=$!
  for _ in $(seq 200); do
    grep -q . "$out/display" 2>/dev/null && break
    kill -0 "$xvnc" 2>/dev/null || break  # it ended: no display will come
    sleep 0.1
  done
  display=$(head -1 "$out/display")
  [[ -n $display ]] || { echo "FAIL: Xvnc reported no display:"; cat "$out/xvnc.log"; exit 1; }
  DISPLAY=:$display xsetroot -mod 7 5 -fg '#c04020' -bg '#203060'
}
