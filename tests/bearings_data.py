"""Bearing data several test files solve with, written once."""

#: 7205B as the catalogue resolves it (`bearingload catalog show 7205B`: NSK's 40° BEA leaflet,
#: d 25, D 52, B 15 mm; 12 balls of 8.7312 mm on d_m 38.5 mm derived from its ratings; f_i 0.52,
#: f_o 0.53 assumed, the ISO/TS 16281 default; E 208 GPa), as the library's keyword arguments.
B7205B = dict(
    ball_diameter=8.7312,
    pitch_diameter=38.5,
    f_i=0.52,
    f_o=0.53,
    modulus=208000.0,
    contact_angle=40.0,
)
