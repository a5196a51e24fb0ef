// The classic look's fixed POV-Ray models (the look before the photographic one, kept so the render
// benchmark can set the two side by side: `Look::classic`). They read the numbers write_pov_include puts
// before them: from the scene (BallR, RailA/RailB/RailH, PocketC/PocketR, NoseMin/NoseMax, Final),
// from the table description (CushionW, CushionUndercut, CushionTopZ, RailW, RailTopZ, FloorZ,
// SightLength/SightWidth, SightC/SightAlongX, the pockets' jaws, throats and liner: RailSlantA/
// RailSlantB, PocketJawed, JawNose0/1, JawIn0/1, PocketAxis, ThroatC/ThroatR/ThroatT0/1, PocketLinerT,
// PocketLipR), from the physics (PocketDepth), from the room
// description (CeilingZ, RoomMargin, LampZ, LampTopZ, LampHalf, LampWall, LampCordR) and the balls'
// colours (BallSrgb). Every CSG cutter overshoots the faces it cuts by Eps: coincident
// faces make POV-Ray pick either surface per ray, which shows as speckled seams.
#include <string>

#include "pov_table.h"

namespace bsim {

namespace {

constexpr std::string_view kClassicHead = R"pov(// ---- fixed models
#include "transforms.inc"
global_settings { assumed_gamma 1.0 max_trace_level 8 }
// A little ambient stands in for the light the bright cloth throws back (no radiosity: too slow).
#default { finish { ambient 0.02 } }

#declare Eps = 0.001;
#declare ApronDepth = 0.23;   // the rail's face below the bed
#declare SlateDepth = 0.028;
#declare Far = <0, 0, -100>;  // where a placeholder keeps an empty CSG valid

// ---- materials
#declare T_Cloth = texture {
  pigment { bozo turbulence 0.3 color_map { [0 srgb <0.05, 0.35, 0.155>] [1 srgb <0.055, 0.37, 0.165>] } scale 0.08 }
  normal { granite 0.06 scale 0.0015 }
  finish { diffuse 0.85 specular 0.02 roughness 0.2 }
}
#declare T_CushionCloth = texture {
  pigment { srgb <0.05, 0.32, 0.14> }
  normal { granite 0.06 scale 0.0015 }
  finish { diffuse 0.85 specular 0.03 roughness 0.15 }
}
// Mahogany with its grain along x; turned for the rails along y.
#declare T_Wood = texture {
  pigment {
    wood turbulence 0.05 octaves 3 scale <0.03, 0.012, 1> rotate y * 90
    color_map { [0.0 srgb <0.20, 0.08, 0.035>] [0.6 srgb <0.28, 0.12, 0.05>] [1.0 srgb <0.16, 0.06, 0.03>] }
  }
  finish { diffuse 0.7 specular 0.12 roughness 0.02 }
}
#declare T_WoodY = texture { T_Wood rotate z * 90 }
#declare T_Liner = texture { pigment { srgb 0.02 } finish { diffuse 0.6 specular 0.12 roughness 0.05 } }
#declare T_Sight = texture { pigment { srgb <0.92, 0.90, 0.84> } finish { diffuse 0.6 specular 0.6 roughness 0.01 } }

)pov";

constexpr std::string_view kClassicTail =
    R"pov(// ---- pocket liners: dark rubber lining each throat through the wood and the cup below the slate
// (the same pockets as the photographic look's); the cushions' jaws stay cloth, as on a real table.
#declare Liners = union {
  sphere { Far, Eps }
  #for (I, 0, PocketCount - 1) PocketLiner(I, CupFloorZ) PocketRoll(I) #end
  texture { T_Liner }
}

// ---- the body under the rails and four legs
#declare TableBody = union {
  box { <OuterMin.u + 0.06, OuterMin.v + 0.06, -ApronDepth - 0.12>, <OuterMax.u - 0.06, OuterMax.v - 0.06, -ApronDepth + Eps> }
  #for (I, 0, 3)
    #local LX = (I < 2 ? OuterMin.u + 0.22 : OuterMax.u - 0.22);
    #local LY = (mod(I, 2) = 0 ? OuterMin.v + 0.22 : OuterMax.v - 0.22);
    box { <LX - 0.09, LY - 0.09, FloorZ - Eps>, <LX + 0.09, LY + 0.09, -ApronDepth - 0.1> }
  #end
  texture { T_Wood scale 3 }
}

#declare Table = union {
  object { Bed }
  object { Cushions }
  object { Rails }
  object { Liners }
  object { Sights }
  object { TableBody }
}

// ---- balls: stripe and number disc are object patterns over the sphere, so no seams; the glyph
// reaches through one half only, else the far side's number shows through.
#declare BallFinish = finish {
  ambient 0.14 diffuse 0.75 specular 0.55 roughness 0.004 phong 0.25 phong_size 180
  reflection { 0.03, 0.07 fresnel } conserve_energy
}
#declare BallWhite = srgb BallSrgb[0];
#declare BallColour = array[16]
#for (N, 0, 15)
  #declare BallColour[N] = srgb BallSrgb[N];
#end
// The number on a white disc at each end of the ball's z axis; the stripe is the band |y| < 0.56 R.
#macro NumberDisc(N, Body)
  #local G = text { ttf "cyrvetic.ttf" str(N, 0, 0) 1, 0 }
  #local G = object { G Center_Trans(G, x + y) scale <0.6 * BallR / 0.72, 0.6 * BallR / 0.72, 2 * BallR> }
  #local Glyphs = union { object { G } object { G rotate y * 180 } }
  pigment {
    object {
      cylinder { -2 * BallR * z, 2 * BallR * z, 0.47 * BallR }
      pigment { Body }
      pigment { object { Glyphs BallWhite srgb 0.02 } }
    }
  }
#end
#macro BallPigment(N)
  #if (N = 0)
    pigment { BallWhite }
  #elseif (N <= 8)
    NumberDisc(N, pigment { BallColour[N] })
  #else
    NumberDisc(N, pigment { object { box { <-2 * BallR, -0.56 * BallR, -2 * BallR>, <2 * BallR, 0.56 * BallR, 2 * BallR> }
                                     BallWhite, BallColour[N] } })
  #end
#end
#declare BallTexture = array[16]
#for (N, 0, 15)
  #declare BallTexture[N] = texture { BallPigment(N) finish { BallFinish } }
#end
// Ball N centred on the origin; a frame places it with its orientation as a matrix.
#macro Ball(N)
  sphere { 0, BallR texture { BallTexture[N] } }
#end

// ---- cue stick of cones and cylinders: the tip's face at the origin, the butt along +x
#declare CueStick = union {
  cylinder { <-0.0005, 0, 0>, <0.011, 0, 0>, 0.0064 pigment { srgb <0.18, 0.30, 0.55> } finish { diffuse 0.8 } }
  cylinder { <0.011, 0, 0>, <0.035, 0, 0>, 0.0065 pigment { srgb <0.95, 0.94, 0.90> } finish { diffuse 0.7 specular 0.4 roughness 0.01 } }
  cone { <0.035, 0, 0>, 0.0065, <0.74, 0, 0>, 0.0105
    pigment { wood turbulence 0.02 scale <1, 0.004, 0.004> rotate z * 90
              color_map { [0 srgb <0.86, 0.74, 0.55>] [1 srgb <0.80, 0.66, 0.46>] } }
    finish { diffuse 0.7 specular 0.5 roughness 0.006 reflection 0.03 } }
  cone { <0.74, 0, 0>, 0.0106, <0.755, 0, 0>, 0.0107 pigment { srgb <0.85, 0.85, 0.82> } finish { specular 0.8 roughness 0.003 metallic reflection 0.2 } }
  cone { <0.755, 0, 0>, 0.0107, <1.0, 0, 0>, 0.0122 texture { T_Wood scale 0.3 } }
  cone { <1.0, 0, 0>, 0.0122, <1.26, 0, 0>, 0.0137 pigment { srgb 0.04 } normal { bumps 0.3 scale 0.0008 } finish { diffuse 0.8 } }
  cone { <1.26, 0, 0>, 0.0137, <1.455, 0, 0>, 0.0144 texture { T_Wood scale 0.3 } }
  cylinder { <1.455, 0, 0>, <1.47, 0, 0>, 0.0145 pigment { srgb 0.03 } finish { diffuse 0.8 specular 0.2 } }
}

// ---- the room: a carpeted floor, panelled walls, a long lamp over the table
plane { z, FloorZ
  pigment { bozo turbulence 0.4 color_map { [0 srgb <0.20, 0.06, 0.05>] [1 srgb <0.26, 0.09, 0.06>] } scale 0.05 }
  normal { granite 0.2 scale 0.01 }
  finish { diffuse 0.7 }
}
box { <OuterMin.u - RoomMargin, OuterMin.v - RoomMargin, FloorZ - 0.1>, <OuterMax.u + RoomMargin, OuterMax.v + RoomMargin, CeilingZ> inverse
  pigment { gradient z color_map { [0 srgb <0.17, 0.11, 0.07>] [0.35 srgb <0.17, 0.11, 0.07>]
                                   [0.35 srgb <0.22, 0.17, 0.11>] [1 srgb <0.22, 0.17, 0.11>] }
            scale 3.4 translate z * FloorZ }
  finish { diffuse 0.6 }
}
union {
  difference {
    box { <-LampHalf.u, -LampHalf.v, LampZ>, <LampHalf.u, LampHalf.v, LampTopZ> }
    box { <-LampHalf.u + LampWall, -LampHalf.v + LampWall, LampZ - 0.01>, <LampHalf.u - LampWall, LampHalf.v - LampWall, LampTopZ - LampWall> }
  }
  cylinder { <0, 0, LampTopZ>, <0, 0, CeilingZ>, LampCordR }
  pigment { srgb <0.07, 0.28, 0.14> } finish { diffuse 0.6 specular 0.5 roughness 0.01 }
  no_shadow
  translate <Middle.u, Middle.v, 0>
}
// a brass band round the shade's rim
difference {
  box { <-LampHalf.u - 0.004, -LampHalf.v - 0.004, LampZ - 0.002>, <LampHalf.u + 0.004, LampHalf.v + 0.004, LampZ + 0.02> }
  box { <-LampHalf.u + 0.01, -LampHalf.v + 0.01, LampZ - 0.01>, <LampHalf.u - 0.01, LampHalf.v - 0.01, LampZ + 0.03> }
  pigment { srgb <0.75, 0.58, 0.28> } finish { diffuse 0.5 specular 0.7 roughness 0.005 metallic reflection 0.2 }
  no_shadow
  translate <Middle.u, Middle.v, 0>
}
box { <-LampHalf.u + LampWall, -LampHalf.v + LampWall, LampZ + 0.005>, <LampHalf.u - LampWall, LampHalf.v - LampWall, LampZ + 0.01>
  pigment { srgb 1 } finish { emission 1 diffuse 0 } no_shadow
  translate <Middle.u, Middle.v, 0>
}

// ---- lights: final has a soft area light without jitter (jitter flickers from frame to frame)
#declare LampColour = srgb <1.0, 0.96, 0.88>;
#if (Final)
  light_source { <Middle.u, Middle.v, LampZ - 0.01> LampColour * 1.6
    area_light x * 2 * (LampHalf.u - 0.03), y * 2 * (LampHalf.v - 0.03), 9, 3 adaptive 1
    fade_distance 1.6 fade_power 2
  }
#else
  light_source { <Middle.u - 0.6 * LampHalf.u, Middle.v, LampZ - 0.01> LampColour * 0.8 fade_distance 1.6 fade_power 2 }
  light_source { <Middle.u + 0.6 * LampHalf.u, Middle.v, LampZ - 0.01> LampColour * 0.8 fade_distance 1.6 fade_power 2 }
#end
// dim room fill, casting no shadows
light_source { <OuterMin.u - 2, OuterMin.v - 2, 2.4> srgb 0.15 shadowless }
light_source { <OuterMax.u + 2, OuterMax.v + 2, 2.4> srgb 0.10 shadowless }

object { Table }
)pov";

}  // namespace

std::string_view pov_classic_models_text() {
  static const std::string text =
      std::string(kClassicHead) + std::string(pov_cushions_and_rails_text()) + std::string(kClassicTail);
  return text;
}

}  // namespace bsim
