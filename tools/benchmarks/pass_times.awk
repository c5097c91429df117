# The pass lines of `vkwater render`'s report ("pass times of frame ...:", then one indented line
# per pass: "  NAME   MS ms  [creates SIZE]"), one per output line as "PREFIX<TAB>NAME<TAB>MS".
# Variables: prefix (tab-separated leading columns), skip_declare (1: leave out the CPU's
# "declare + compile graph" line). Shared by frame_ratio.sh and scene_times.sh.
/^pass times/ { on = 1; next }
on && /^  [^ ]/ && / ms/ {
  line = substr($0, 3); sub(/ creates .*/, "", line); sub(/ ms.*/, "", line)
  n = split(line, f, " "); ms = f[n]; name = f[1]; for (i = 2; i < n; i++) name = name " " f[i]
  if (skip_declare && name ~ /^declare/) next
  printf "%s\t%s\t%s\n", prefix, name, ms
}
on && !/^  / { on = 0 }
