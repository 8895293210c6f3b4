# sphere_scene.sh - sourced by the bench tests: the integrating sphere
# (radius 1 m, inward, a 1000 lm point source at its centre) with a points
# grid on its wall. sphere_points N sets $points to N points spread over the
# wall (a Fibonacci lattice), 0.999 m from the centre, normals towards it;
# sphere_scene RHO prints the scene of reflectance RHO with those points.
sphere_points() {
  points=$(awk -v n="$1" 'BEGIN { pi = atan2(0, -1); R = 0.999
    for (i = 0; i < n; ++i) {
      z = 1 - 2 * (i + 0.5) / n; r = sqrt(1 - z * z); ph = i * pi * (3 - sqrt(5))
      x = r * cos(ph); y = r * sin(ph)
      printf "%s{\"p\": [%.9f, %.9f, %.9f], \"n\": [%.9f, %.9f, %.9f]}", (i ? ", " : ""), R*x, R*y, R*z, -x, -y, -z
    } }')
}
sphere_scene() { # reflectance
  printf '{"version": 1,\n "surfaces": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "inward": true, "reflectance": %s}],\n' "$1"
  printf ' "luminaires": [{"type": "point", "position": [0, 0, 0], "flux_lm": 1000}],\n'
  printf ' "grids": [{"name": "wall", "type": "points", "points": [%s]}]}\n' "$points"
}
