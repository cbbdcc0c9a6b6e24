# grid_png.sh - `luxcalc grid --png`: a PNG of the plane is written atomically, never half.
. tests/cli/lib.sh
L=samples/ies/spot_warn_30deg_800lm.ies
run grid --ies $L --at 2,1.5,2.8 --plane z=0.8 --area 0:4,0:3 --spacing 0.1 --png "$T/g.png" --summary
expect_rc 0 "grid --png"
if [ "$(head -c 8 "$T/g.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; then ok "PNG signature"; else notok "PNG signature" "$(head -c 8 "$T/g.png" | od -c)"; fi
# IHDR width and height (big-endian at bytes 16-23): the plot keeps the plane's 4:3 aspect
wh=$(od -An -tu1 -j16 -N8 "$T/g.png" | awk '{print ($1*16777216+$2*65536+$3*256+$4) "x" ($5*16777216+$6*65536+$7*256+$8)}')
w=${wh%x*}; h=${wh#*x}
if [ "$w" -gt "$h" ] && [ "$w" -ge 560 ]; then ok "plot size ${wh} follows the area"; else notok "plot size" "$wh"; fi
echo keep > "$T/keep.png"
run grid --ies $L --at 2,1.5,2.8 --plane z=0.8 --area 0:4,0:3 --spacing 0.1 --png /nonexistent-dir/g.png --summary
expect_rc 2 "--png into a missing directory is an input error"
expect_err_match "nonexistent-dir" "the message names the file"
if [ -z "$(ls "$T" | grep -v -e '^g.png$' -e '^keep.png$' -e '^out$' -e '^err$')" ]; then ok "no temporary file left"; else notok "temporary files" "$(ls "$T")"; fi
# the isolux plot of a scene's luminaires on a plane of the flags, a white background, imperial units
run grid --scene samples/scenes/office.scene --plane z=0.75 --area 0:4,0:3 --spacing 0.25 --points-at centres \
  --png "$T/s.png" --png-style white --units imperial --summary
expect_rc 0 "grid --scene --png"
if [ "$(head -c 8 "$T/s.png" | od -An -tx1 | tr -d ' \n')" = 89504e470d0a1a0a ]; then ok "grid --scene writes a PNG"; else notok "grid --scene writes a PNG" "no PNG"; fi
expect_out_match '^E_avg,' "the summary still printed"
run grid --ies $L --at 2,1.5,2.8 --plane z=0.8 --area 0:4,0:3 --spacing 0.1 --png "$T/w.png" --png-style pink --summary
expect_rc 1 "--png-style takes falsecolor or white"
# scene --png DIR creates DIR (as spd --report DIR does) and names the file after scene and receiver
run scene samples/scenes/office.scene --png "$T/new/dir"
expect_rc 2 "scene --png creates one level, not a path of missing directories (an input error)"
run scene samples/scenes/office.scene --png "$T/newdir"
expect_rc 0 "scene --png into a directory that does not exist yet"
if [ -f "$T/newdir/office_desk.png" ]; then ok "scene --png creates DIR"; else notok "scene --png creates DIR" "$(ls "$T/newdir" 2>&1)"; fi
