# Sourced by docs/trace-study.sh and docs/image-study.sh: `study_case CASE` copies
# cases/CASE.toml into "$out" with the study camera, 64×64 pixels below the lamp's line of
# sight, so that no pixel sees the lamp and the image measures reflected light only.
study_case() {
  cp "cases/$1.toml" "$out/$1.toml"
  cat >> "$out/$1.toml" <<'TOML'

[[camera]]
name = "study"
position = [0.278, 0.2, -0.8]
look_at = [0.278, 0.2, 0.5592]
fov_deg = 28
resolution = [64, 64]
TOML
}
