// SPDX-FileCopyrightText: 2026 The pgloss authors
// SPDX-License-Identifier: Apache-2.0
// POV-Ray 3.7 version of examples/tracer/scenes/povray-diffuse.scene: Experiment 1's stimulus
// environment (Pellacini, Ferwerda & Greenberg 2000, Fig. 4) with a Lambertian grey sphere.
// Rendered headlessly by tests/tracer (Debian's povray 3.7):
//   povray +Istimulus-diffuse.pov +Oout.exr +FE -D +W128 +H96 +A0.0 +AM1 +R3 [Declare=RADIOSITY=1]
// RADIOSITY=0 renders direct light only; RADIOSITY=1 adds POV-Ray's radiosity (5 bounces).
//
// Coordinates: the tracer is right-handed (y up, camera looking towards -z); POV-Ray is
// left-handed. Every z below is the tracer's z negated, which keeps +x to the right of the image.
//
// Photometry. A POV-Ray light of colour C with fade_power 2 gives a Lambertian surface
// (diffuse 1, pigment rho) the radiance  rho * C * 2 / (1 + (d/fd)^2) * cos(theta)  which, for
// d >> fd, is rho * C * 2 fd^2 / d^2 * cos(theta). The tracer's isotropic area light of
// "radiance" Le (intensity Le dA per element dA) gives rho/pi * Le * A / d^2 * cos(theta).
// So C = Le A / (2 pi fd^2); with Le = 16, A = 1 m^2, fd = 0.001 m, C = 2546479.1.
// POV-Ray divides C among the area light's n1 x n2 point lights.
#version 3.7;
#ifndef (RADIOSITY) #declare RADIOSITY = 0; #end

global_settings {
  assumed_gamma 1.0
  ambient_light rgb 0
  max_trace_level 10
  #if (RADIOSITY)
  radiosity {
    pretrace_start 0.08
    pretrace_end 0.004
    count 600
    nearest_count 10
    error_bound 0.25
    recursion_limit 5
    low_error_factor 0.5
    gray_threshold 0
    minimum_reuse 0.005
    brightness 1
    adc_bailout 0.001
    always_sample off
  }
  #end
}

#declare Le = 16;
#declare FadeDist = 0.001;
#declare LightColour = Le * 1.0 / (2 * pi * FadeDist * FadeDist);

// The tracer's fov=48 is vertical; POV-Ray's angle is horizontal: tan(h/2) = (4/3) tan(v/2).
camera {
  perspective
  location <0, 1.5, -1.95>
  look_at  <0, 0.45, 0.5>
  right x * 4/3
  up y
  angle 2 * degrees(atan(4/3 * tan(radians(48/2))))
}

#declare Matte = finish { ambient 0 emission 0 diffuse 1 specular 0 phong 0 reflection 0 brilliance 1 }

// The box (inside seen), 3-D checkerboard of 0.5 m cells offset by 0.125 m, as the tracer's
// "checker". Negating z swaps the parity of the cells, hence white first here.
box {
  <-2, 0, -2>, <2, 3, 2>
  pigment {
    checker color rgb 0.767, color rgb 0.03
    scale 0.5
    translate <0.125, 0.125, -0.125>
  }
  finish { Matte }
}

sphere { <0, 0.5, 0.5>, 0.5 pigment { color rgb 0.193 } finish { Matte } }

// 1 m x 1 m light centred under the ceiling (the tracer's corner -0.5,2.999,-1.0 + edges),
// as an N x N array of point lights. POV-Ray spaces them axis/(N-1) apart from one edge to the
// other (so the edges carry as much weight as the middle), which is the main reason its
// penumbra differs from the tracer's continuous emitter (see examples/povray/README.md).
#declare N = 13;
light_source {
  <0, 2.999, 0.5>
  color rgb LightColour
  area_light <1, 0, 0>, <0, 0, 1>, N, N
  jitter
  area_illumination on
  fade_distance FadeDist
  fade_power 2
}

// The emitter's back: POV-Ray's point lights shine both ways, and 1 mm under the ceiling they
// would light the ceiling above them enormously (1/d^2), which radiosity then spreads around.
// The tracer's light is a one-sided black quad; this black slab between the light and the
// ceiling does the same for POV-Ray (it is above the point lights, so it shadows nothing below).
box {
  <-0.5, 2.9995, 0>, <0.5, 3.0, 1>
  pigment { color rgb 0 }
  finish { ambient 0 emission 0 diffuse 0 specular 0 }
}

