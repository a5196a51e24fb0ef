// The fixed POV-Ray models of the shared include, the photographic look. They read the numbers
// write_pov_include puts before them: from the scene (BallR, RailA/RailB/RailH, PocketC/PocketR,
// NoseMin/NoseMax, Final), from the table description (CushionW, CushionUndercut, CushionTopZ, RailW,
// RailTopZ, FloorZ, SightLength/SightWidth, SightC/SightAlongX; the pockets' jaws, throats and liner:
// RailSlantA/RailSlantB, PocketJawed, JawNose0/1, JawIn0/1, PocketAxis, ThroatC/ThroatR/ThroatT0/1,
// PocketLinerT, PocketLipR),
// from the physics (PocketDepth: how deep a pocketed ball rests), from the room description
// (CeilingZ, RoomMargin, LampZ, LampTopZ, LampHalf, LampWall, LampCordR) and the balls' colours
// (BallSrgb). Every CSG cutter overshoots the faces it cuts by Eps: coincident faces make POV-Ray pick
// either surface per ray, which shows as speckled seams.
//
// Light, after how pool halls are lit and photographed: one rectangular lamp over the bed, its
// light cut off by the shade (a spotlight cone), so a pool of light lies on the cloth and falls off
// towards the rails while the room stays dim; a few wall sconces; the light the cloth throws back
// (bounce light) by a shadowless green light from below the bed instead of radiosity, which cost
// several times as much a frame and shimmered between frames (README "Quality presets").
// Materials: worsted cloth (a woven normal, a sheen at grazing angles by the `aoi` pattern),
// phenolic balls with a clear coat (fresnel reflection with ior 1.5: 4 % head-on, all at grazing,
// after Schlick's approximation of the Fresnel equations), lacquered mahogany (the same clear coat).
#include <string>

#include "pov_table.h"

namespace bsim {

namespace {

constexpr std::string_view kModelsHead = R"pov(// ---- fixed models (the photographic look)
#include "transforms.inc"
global_settings { assumed_gamma 1.0 max_trace_level 6 adc_bailout 1 / 128 }
// No ambient: the room's light comes from its lamps and the bounce light below.
#default { finish { ambient 0 diffuse 0.8 } }

#declare Eps = 0.001;
#declare ApronDepth = 0.23;   // the rail's face below the bed
#declare SlateDepth = 0.028;
#declare Far = <0, 0, -100>;  // where a placeholder keeps an empty CSG valid
#declare ClearCoat = interior { ior 1.5 }  // lacquer and phenolic resin: fresnel needs an ior

// ---- materials
// Worsted wool cloth: the weave's fine grain as a low bump noise (a regular weave of threads 0.5 mm
// apart aliased into moire rings at 1280x720), a faint mottle of the felt's nap (broad patches and a
// finer grain, as in a close photograph of worn cloth), and the fibres' sheen where the cloth
// is seen at a grazing angle (aoi is 1 head-on, 0.5 at grazing).
#declare N_Weave = normal { bumps 0.05 scale 0.0012 }
#declare P_ClothFelt = pigment {
  average pigment_map {
    [2 bozo turbulence 0.5 color_map { [0 srgb <0.032, 0.315, 0.152>] [1 srgb <0.04, 0.345, 0.168>] } scale 0.12]
    [1 granite color_map { [0 srgb <0.029, 0.29, 0.14>] [1 srgb <0.043, 0.36, 0.175>] } scale 0.05]
  }
}
#declare P_Cloth = pigment {
  aoi pigment_map {
    [0.5 srgb <0.16, 0.44, 0.28>]
    [0.62 P_ClothFelt]
    [1.0 P_ClothFelt]
  }
}
#declare T_Cloth = texture {
  pigment { P_Cloth }
  normal { N_Weave }
  finish { diffuse 0.9 brilliance 0.8 specular 0.03 roughness 0.25 }
}
#declare T_CushionCloth = texture { T_Cloth }
// Mahogany under lacquer: grain along x (turned for the rails along y), a little figure in the
// normal, the clear coat's tight highlight (a mirroring coat cost a tenth of the frame and turned the
// near rail into a white bar in wide shots).
#declare T_Wood = texture {
  pigment {
    wood turbulence <0.04, 0.3, 0.04> octaves 4 scale <0.006, 0.006, 1> rotate y * 90
    color_map { [0.0 srgb <0.23, 0.085, 0.035>] [0.45 srgb <0.30, 0.12, 0.05>] [0.7 srgb <0.20, 0.07, 0.03>]
                [1.0 srgb <0.27, 0.10, 0.045>] }
  }
  normal { wood 0.015 turbulence <0.04, 0.3, 0.04> scale <0.006, 0.006, 1> rotate y * 90 }
  finish { diffuse 0.65 specular 0.6 roughness 0.0025 }
}
#declare T_WoodY = texture { T_Wood rotate z * 90 }
#declare T_DarkWood = texture {
  pigment { wood turbulence 0.1 scale <0.02, 0.02, 1> rotate y * 90
            color_map { [0 srgb <0.12, 0.05, 0.025>] [1 srgb <0.17, 0.07, 0.035>] } }
  finish { diffuse 0.6 specular 0.2 roughness 0.01 }
}
// Mother-of-pearl sights.
#declare T_Sight = texture {
  pigment { srgb <0.93, 0.91, 0.86> }
  finish { diffuse 0.6 specular 0.7 roughness 0.004 irid { 0.2 thickness 0.4 turbulence 0.3 } }
}

)pov";

// The cushions, the wooden rail and its sights: one model for both looks.
constexpr std::string_view kCushionsAndRails =
    R"pov(// ---- cushions: a nose profile (K-66-like, nose at the rail's height) swept along each nose line,
// on the right of A->B seen from above, reaching back into the wood and on past each nose end: a
// square end by its width (mitred by the next cushion), a jaw as far as its facing runs on (RailSlantA/
// RailSlantB per metre behind the nose) before CushionCuts cut it.
#macro CushionExt(Slant) (Slant < 0 ? CushionW : Slant * (CushionW + 0.012) + 0.005) #end
#macro Cushion(I)
  #local A = RailA[I];
  #local H = RailH[I];
  #local D = vnormalize(RailB[I] - A);
  #local L = vlength(RailB[I] - A);
  #local N = <-D.v, D.u>;
  #local Top = CushionTopZ;
  prism {
    linear_sweep linear_spline -CushionExt(RailSlantA[I]), L + CushionExt(RailSlantB[I]), 11,
    <CushionUndercut, -Eps>, <0.0055, H * 0.52>, <0.0012, H * 0.85>, <0.0, H>, <0.0006, H + 0.0016>,
    <0.0035, H + 0.0034>, <0.015, H + 0.35 * (Top - H)>, <CushionW, Top>,
    <CushionW + 0.012, Top>, <CushionW + 0.012, -Eps>, <CushionUndercut, -Eps>
    matrix <N.u, N.v, 0, D.u, D.v, 0, 0, 0, 1, A.u, A.v, 0>
  }
#end

// ---- pockets, from the table description's pocket mouths: each jawed pocket's two cushions end
// at their nose ends (JawNose0/1) and are cut, with the wood behind them, along facings at the WPA
// angle (JawIn0/1: each facing's normal into the opening); the throat between the facings closes in
// a round back (ThroatC, ThroatR, touching the facings at ThroatT0/1). A bare pocket (no jaws) opens
// on its drop circle. Throat(I, Grow, Z0, Z1): that opening grown by Grow, from Z0 up to Z1.
#macro Throat(I, Grow, Z0, Z1)
  #if (PocketJawed[I])
    #local F0 = ThroatT0[I] - JawNose0[I];
    #local F1 = ThroatT1[I] - JawNose1[I];
    #local N0 = JawNose0[I] - JawIn0[I] * Grow - F0 * (Grow / vlength(F0));
    #local N1 = JawNose1[I] - JawIn1[I] * Grow - F1 * (Grow / vlength(F1));
    #local T0 = ThroatT0[I] - JawIn0[I] * Grow;
    #local T1 = ThroatT1[I] - JawIn1[I] * Grow;
    union {
      cylinder { <ThroatC[I].u, ThroatC[I].v, Z0>, <ThroatC[I].u, ThroatC[I].v, Z1>, ThroatR[I] + Grow }
      prism { linear_sweep linear_spline -Z1, -Z0, 5, N0, T0, T1, N1, N0 rotate -x * 90 }
    }
  #else
    cylinder { <PocketC[I].u, PocketC[I].v, Z0>, <PocketC[I].u, PocketC[I].v, Z1>, PocketR[I] + Grow }
  #end
#end
// The hole through the slate and the cup below: the throat and the physics' drop circle together.
#macro Hole(I, Grow, Z0, Z1)
  union {
    Throat(I, Grow, Z0, Z1)
    cylinder { <PocketC[I].u, PocketC[I].v, Z0>, <PocketC[I].u, PocketC[I].v, Z1>, PocketR[I] + Grow }
  }
#end
// A box round all of pocket I's opening, grown by Grow, from Z0 to Z1: each pocket's cutter is
// bounded by it, so a ray far from a pocket tests one box instead of the pocket's shapes (POV-Ray
// bounds no object inside a CSG by itself).
#macro PocketBound(I, Grow, Z0, Z1)
  #local C = PocketC[I];
  #local D = max(PocketR[I], vlength(ThroatC[I] - C) + ThroatR[I]);
  #if (PocketJawed[I])
    #local D = max(D, vlength(JawNose0[I] - C), vlength(JawNose1[I] - C));
  #end
  #local D = D + Grow + 0.01;
  bounded_by { box { <C.u - D, C.v - D, Z0 - Eps>, <C.u + D, C.v + D, Z1 + Eps> } }
#end
#declare InnerMin = NoseMin - <CushionW, CushionW>;
#declare InnerMax = NoseMax + <CushionW, CushionW>;
// Inside the wood, above the slate's underside: where no liner lies (the facings there are cloth).
#declare InsideWood = box { <InnerMin.u, InnerMin.v, -SlateDepth + Eps>, <InnerMax.u, InnerMax.v, 1> }
#declare OutsideWood = box { <InnerMin.u, InnerMin.v, -2>, <InnerMax.u, InnerMax.v, 2> inverse }
// A pocketed ball rests PocketDepth below the bed on the cup's leather floor.
#declare CupFloorZ = -PocketDepth - 0.0005;
// The slate: the hole, its edge rounded (PocketLipR) where the cloth wraps over it into the drop.
#declare PocketHoles = union {
  sphere { Far, Eps }
  #for (I, 0, PocketCount - 1)
    union {
      Hole(I, 0, -1, 1)
      difference {
        cylinder { <PocketC[I].u, PocketC[I].v, -PocketLipR - Eps>, <PocketC[I].u, PocketC[I].v, Eps>, PocketR[I] + PocketLipR }
        torus { PocketR[I] + PocketLipR, PocketLipR rotate x * 90 translate <PocketC[I].u, PocketC[I].v, -PocketLipR> }
      }
      PocketBound(I, PocketLipR, -1, 1)
    }
  #end
}
// The cushions: cut along the facings; in the wood, where the liner lies, back behind it.
#declare CushionCuts = union {
  sphere { Far, Eps }
  #for (I, 0, PocketCount - 1)
    union {
      Throat(I, 0, -1, 1)
      intersection { Throat(I, PocketLinerT + Eps, -1, 1) object { OutsideWood } }
      PocketBound(I, PocketLinerT, -1, 1)
    }
  #end
}
// The wood: the throat and its liner, and below the slate the cup and its leather.
#declare PocketCuts = union {
  sphere { Far, Eps }
  #for (I, 0, PocketCount - 1)
    union {
      Throat(I, PocketLinerT, -SlateDepth - Eps, 1)
      Hole(I, PocketLinerT, CupFloorZ - PocketLinerT - Eps, -SlateDepth)
      PocketBound(I, PocketLinerT, CupFloorZ - PocketLinerT - Eps, 1)
    }
  #end
}
// The leather lining pocket I: the throat through the wood, and below the slate the cup with its
// floor at FloorZ (PocketLiner); where the throat leaves the wood's top the leather rolls over the
// edge in a round bead (PocketRoll), the wood's rounded cut.
#declare RollR = 0.004;  // m, the bead's radius; it stands 1.5 mm proud of the wood
#macro PocketRoll(I)
  #local Z = RailTopZ + 0.0015 - RollR;
  #if (PocketJawed[I])
    #local A = PocketAxis[I];
    #local M = (ThroatT0[I] + ThroatT1[I]) / 2;
    intersection {
      union {
        intersection {
          torus { ThroatR[I] + RollR, RollR rotate x * 90 translate <ThroatC[I].u, ThroatC[I].v, Z> }
          plane { -<A.u, A.v, 0>, -vdot(A, M) }
        }
        #for (K, 0, 1)
          #local N = (K = 0 ? JawNose0[I] - JawIn0[I] * RollR : JawNose1[I] - JawIn1[I] * RollR);
          #local T = (K = 0 ? ThroatT0[I] - JawIn0[I] * RollR : ThroatT1[I] - JawIn1[I] * RollR);
          cylinder { <N.u, N.v, Z>, <T.u, T.v, Z>, RollR }
        #end
      }
      object { OutsideWood }
    }
  #else
    intersection {
      torus { PocketR[I] + RollR, RollR rotate x * 90 translate <PocketC[I].u, PocketC[I].v, Z> }
      object { OutsideWood }
    }
  #end
#end
#macro PocketLiner(I, FloorZ)
  difference {
    union {
      Throat(I, PocketLinerT, -SlateDepth - Eps / 2, RailTopZ - Eps)
      Hole(I, PocketLinerT, FloorZ - PocketLinerT, -SlateDepth)
    }
    Throat(I, 0, -SlateDepth - Eps, 1)
    Hole(I, 0, FloorZ, -SlateDepth + Eps / 2)
    object { InsideWood }
  }
#end

#declare OuterMin = InnerMin - <RailW, RailW>;
#declare OuterMax = InnerMax + <RailW, RailW>;
#declare Middle = (NoseMin + NoseMax) / 2;

// ---- the bed: slate under cloth, holed by the pockets
#declare Bed = difference {
  box { <InnerMin.u - Eps, InnerMin.v - Eps, -SlateDepth>, <InnerMax.u + Eps, InnerMax.v + Eps, 0> }
  object { PocketHoles }
  texture { T_Cloth }
}

// Each cushion cut on its own, so each keeps a tight bounding box: a ray over the cloth meets none.
#declare Cushions = union {
  sphere { Far, Eps }
  #for (I, 0, RailCount - 1)
    difference { Cushion(I) object { CushionCuts } }
  #end
  texture { T_CushionCloth }
}

// ---- the wooden rails: four mitred pieces (the grain runs along each), bevelled on the outer
// edge, cut by the pockets. Separate pieces keep tight bounding boxes.
#declare Bevel = 0.016;
#macro RailPiece(P0, P1, P2, P3, Out, Tex)
  difference {
    prism { linear_sweep linear_spline -RailTopZ, ApronDepth, 5, P0, P1, P2, P3, P0 rotate -x * 90 }
    // the bevel: a plane through the outer top edge, pulled in by Bevel, leaning out at 45 degrees
    plane { <Out.u, Out.v, 1>, 0 translate <P2.u - Out.u * Bevel, P2.v - Out.v * Bevel, RailTopZ> inverse }
    object { PocketCuts }
    texture { Tex }
  }
#end
#declare Rails = union {
  RailPiece(<InnerMin.u, InnerMax.v>, <InnerMax.u, InnerMax.v>, <OuterMax.u, OuterMax.v>, <OuterMin.u, OuterMax.v>, <0, 1>, T_Wood)
  RailPiece(<InnerMax.u, InnerMin.v>, <InnerMin.u, InnerMin.v>, <OuterMin.u, OuterMin.v>, <OuterMax.u, OuterMin.v>, <0, -1>, T_Wood)
  RailPiece(<InnerMax.u, InnerMax.v>, <InnerMax.u, InnerMin.v>, <OuterMax.u, OuterMin.v>, <OuterMax.u, OuterMax.v>, <1, 0>, T_WoodY)
  RailPiece(<InnerMin.u, InnerMin.v>, <InnerMin.u, InnerMax.v>, <OuterMin.u, OuterMax.v>, <OuterMin.u, OuterMin.v>, <-1, 0>, T_WoodY)
}

// ---- diamond sights: inlaid in the rails' tops where the table description puts them, the long
// diagonal along the rail
#macro SightAt(P, AlongX)
  #local L = (AlongX ? SightLength : SightWidth) / 2;
  #local W = (AlongX ? SightWidth : SightLength) / 2;
  prism {
    linear_sweep linear_spline -(RailTopZ + 0.0004), -(RailTopZ - 0.002), 5, <L, 0>, <0, W>, <-L, 0>, <0, -W>, <L, 0>
    rotate -x * 90 translate <P.u, P.v, 0>
  }
#end
#declare Sights = union {
  sphere { Far, Eps }
  #for (I, 0, SightCount - 1) SightAt(SightC[I], SightAlongX[I]) #end
  texture { T_Sight }
}

)pov";

constexpr std::string_view kModelsTail =
    R"pov(// ---- pockets: a leather liner lines each throat through the wood, and below the slate a leather cup
// (a drop pocket) holds the pocketed balls PocketDepth below the bed, where the physics leaves them,
// so a ball is seen to drop in and to lie there. The liner is near-black leather with a faint grain,
// so the opening reads dark from across the room; the cup below the slate is a warmer brown, so the
// lamp's light that falls through the hole shows its inside and a ball lying in it. The bead the
// liner rolls over the wood's edge is polished by hands and balls: its highlight outlines the opening.
#declare T_PocketLeather = texture {
  gradient z
  texture_map {
    [0.5 pigment { srgb <0.18, 0.09, 0.04> } normal { granite 0.03 scale 0.006 } finish { diffuse 0.7 specular 0.04 roughness 0.04 }]
    [0.5 pigment { srgb <0.065, 0.038, 0.024> } normal { granite 0.06 scale 0.006 } finish { diffuse 0.7 specular 0.05 roughness 0.03 }]
  }
  translate -z * (0.5 + SlateDepth)  // the cup's brown below the slate's underside, the liner's black above
}
#declare T_PocketBead = texture {
  pigment { srgb <0.075, 0.044, 0.028> }
  finish { diffuse 0.65 specular 0.35 roughness 0.006 }
}
#declare Liners = union {
  sphere { Far, Eps }
  #for (I, 0, PocketCount - 1)
    PocketLiner(I, CupFloorZ)
    object { PocketRoll(I) texture { T_PocketBead } }
  #end
  texture { T_PocketLeather }
}

// ---- the body under the rails and four turned legs
#declare TableBody = union {
  box { <OuterMin.u + 0.06, OuterMin.v + 0.06, -ApronDepth - 0.12>, <OuterMax.u - 0.06, OuterMax.v - 0.06, -ApronDepth + Eps> }
  #for (I, 0, 3)
    #local LX = (I < 2 ? OuterMin.u + 0.22 : OuterMax.u - 0.22);
    #local LY = (mod(I, 2) = 0 ? OuterMin.v + 0.22 : OuterMax.v - 0.22);
    union {
      box { <-0.09, -0.09, FloorZ - Eps>, <0.09, 0.09, FloorZ + 0.08> }
      cone { <0, 0, FloorZ + 0.08>, 0.075, <0, 0, -ApronDepth - 0.1>, 0.1 }
      translate <LX, LY, 0>
    }
  #end
  texture { T_DarkWood }
}

// ---- what use leaves on a table: the foot spot, a thin cloth disc where the rack's apex stands (a
// quarter of the bed's length from the foot cushion, as the WPA marks it), and a cube of blue chalk
// on the near long rail
#declare FootSpot = cylinder {
  <NoseMax.u - (NoseMax.u - NoseMin.u) / 4, Middle.v, -Eps>, <NoseMax.u - (NoseMax.u - NoseMin.u) / 4, Middle.v, 0.0002>, 0.0127
  pigment { srgb <0.86, 0.84, 0.78> } normal { N_Weave } finish { diffuse 0.85 specular 0.02 roughness 0.2 }
}
#declare ChalkSide = 0.022;
#declare Chalk = intersection {
  box { -ChalkSide / 2, ChalkSide / 2 }
  sphere { 0, ChalkSide * 0.8 }  // the cube's corners worn round
  sphere { <0, 0, ChalkSide * 0.5 + 0.06>, 0.0615 inverse }  // the hollow a cue tip wears in its top
  pigment { granite color_map { [0 srgb <0.13, 0.32, 0.62>] [1 srgb <0.20, 0.40, 0.70>] } scale 0.004 }
  finish { diffuse 0.9 }
  rotate z * 23
  translate <NoseMin.u + 0.28 * (NoseMax.u - NoseMin.u), InnerMin.v - RailW / 2, RailTopZ + ChalkSide / 2>
}

#declare Table = union {
  object { Bed }
  object { Cushions }
  object { Rails }
  object { Liners }
  object { Sights }
  object { TableBody }
  object { FootSpot }
  object { Chalk }
}

// ---- balls of phenolic resin under a clear coat: diffuse colour, the lamp mirrored by fresnel
// reflection (4 % head-on), a tight highlight. Stripe and number circle are object patterns over
// the sphere, so no seams; the glyph reaches through one half only, else the far side's number
// shows through. Proportions of a standard (Aramith-style) set: the stripe is the middle half of the
// ball's height (|y| < R/2), the number circle 25 mm across, centred on the stripe.
#declare BallFinish = finish {
  diffuse 0.78 specular 0.35 roughness 0.0015 brilliance 1.2
  reflection { 0.0, 1.0 fresnel } conserve_energy
}
#declare BallWhite = srgb BallSrgb[0];
#declare BallColour = array[16]
#for (N, 0, 15)
  #declare BallColour[N] = srgb BallSrgb[N];
#end
#declare StripeHalf = 0.5 * BallR;
#declare DiscR = 0.4375 * BallR;
#macro NumberDisc(N, Body, T)
  #local G = text { ttf "cyrvetic.ttf" str(N, 0, 0) 1, 0 }
  #local G = object { G Center_Trans(G, x + y) scale <0.55 * BallR / 0.72, 0.55 * BallR / 0.72, 2 * BallR> }
  #local Glyphs = union { object { G } object { G rotate y * 180 } }
  pigment {
    object {
      cylinder { -2 * BallR * z, 2 * BallR * z, DiscR }
      pigment { Body }
      #if (T > 0)  // a ball's streak: the number turns too fast to read, a plain disc
        pigment { color BallWhite transmit T }
      #else
        pigment { object { Glyphs BallWhite srgb 0.02 } }
      #end
    }
  }
#end
// T: how much the ball lets through (0, but for the streak of a motion-blurred ball).
#macro BallPigment(N, T)
  #local White = color BallWhite transmit T;
  #local Colour = color BallColour[N] transmit T;
  #if (N = 0)
    pigment { White }
  #elseif (N <= 8)
    NumberDisc(N, pigment { Colour }, T)
  #else
    NumberDisc(N, pigment { object { box { <-2 * BallR, -StripeHalf, -2 * BallR>, <2 * BallR, StripeHalf, 2 * BallR> }
                                     White, Colour } }, T)
  #end
#end
#declare BallTexture = array[16]
#for (N, 0, 15)
  #declare BallTexture[N] = texture { BallPigment(N, 0) finish { BallFinish } }
#end
// Ball N centred on the origin; a frame places it with its orientation as a matrix.
#macro Ball(N)
  sphere { 0, BallR texture { BallTexture[N] } interior { ClearCoat } }
#end
// A piece of a fast ball's streak (pov_frame.h): the capsule the ball sweeps from the origin to
// <L, 0, D>, laid out with x along the piece as the camera sees it and z towards the camera. Its
// front lets through what the ball does not cover of the shutter's time at that point of the
// picture, W times the length of its centre line (x from 0 to Lc) within its chord there (half
// length sqrt(BallR^2 - y^2)); its back lets all through, so each point counts once. Its colours
// are the ball's own, placed by Turn (the ball's orientation and centre half-way along the piece),
// so a stripe or a number circle is smeared along the way as the shutter sees it; the number itself,
// turning too fast to read, is left out.
#declare StreakCover = function(X, Y, Lc, W) {
  min(1, W * max(0, min(X + sqrt(max(BallR * BallR - Y * Y, 0)), Lc) - max(X - sqrt(max(BallR * BallR - Y * Y, 0)), 0)))
}
#macro BallStreak(N, L, D, Lc, W, Turn)
  #local Clear = BallPigment(N, 1)
  #local Clear = pigment { Clear transform { Turn } }
  #local Solid = BallPigment(N, 0.0001)
  #local Solid = pigment { Solid transform { Turn } }
  merge {
    sphere { 0, BallR }
    sphere { <L, 0, D>, BallR }
    #if (vlength(<L, 0, D>) > 1e-6) cylinder { 0, <L, 0, D>, BallR } #end
    texture {
      pigment { function { StreakCover(x, y, Lc, W) } pigment_map { [0 Clear] [1 Solid] } }
      finish { diffuse 0.78 specular 0.35 roughness 0.002 }
    }
    interior_texture { pigment { rgbt 1 } }
    no_shadow
  }
#end
// The shadow of a blurred ball: one unseen ball at the frame's instant (the soft lamp blurs it anyway;
// shadows through every transparent copy would cost more than all the rest of the frame).
#declare BallShadow = sphere { 0, BallR no_image no_reflection pigment { srgb 0 } }

// ---- cue stick of cones and cylinders: the tip's face at the origin, the butt along +x. Its parts,
// tip first, each from CuePartStart to CuePartEnd (m from the tip's face), its radius going from
// CuePartR0 to CuePartR1: the leather tip, the ferrule, the maple shaft, the joint's ring, the
// forearm, the wrap, the butt sleeve and the butt cap.
#declare CueLength = 1.47;
#declare CueParts = 8;
#declare CuePartStart = array[8] { -0.0005, 0.011, 0.035, 0.74, 0.755, 1.0, 1.26, 1.455 }
#declare CuePartEnd = array[8] { 0.011, 0.035, 0.74, 0.755, 1.0, 1.26, 1.455, 1.47 }
#declare CuePartR0 = array[8] { 0.0064, 0.0065, 0.0065, 0.0106, 0.0107, 0.0122, 0.0137, 0.0145 }
#declare CuePartR1 = array[8] { 0.0064, 0.0065, 0.0105, 0.0107, 0.0122, 0.0137, 0.0144, 0.0145 }
#macro CuePart(I)
  #local A = <CuePartStart[I], 0, 0>;
  #if (CuePartR0[I] = CuePartR1[I])
    cylinder { A, <CuePartEnd[I], 0, 0>, CuePartR0[I] }
  #else
    cone { A, CuePartR0[I], <CuePartEnd[I], 0, 0>, CuePartR1[I] }
  #end
#end
// Part I's colours as a pigment's body, letting T through.
#macro CueColour(I, T)
  #switch (I)
    #case (0) srgbt <0.18, 0.30, 0.55, T> #break
    #case (1) srgbt <0.95, 0.94, 0.90, T> #break
    #case (2)
      wood turbulence 0.02 scale <1, 0.004, 0.004> rotate z * 90
      color_map { [0 srgbt <0.86, 0.74, 0.55, T>] [1 srgbt <0.80, 0.66, 0.46, T>] }
      #break
    #case (3) srgbt <0.85, 0.85, 0.82, T> #break
    #case (5) srgbt <0.04, 0.04, 0.04, T> #break
    #case (7) srgbt <0.03, 0.03, 0.03, T> #break
    #else srgbt <0.25, 0.09, 0.04, T>
  #end
#end
// Part I's finish (and the wrap's grip).
#macro CueFinish(I)
  #switch (I)
    #case (0) finish { diffuse 0.8 } #break
    #case (1) finish { diffuse 0.7 specular 0.4 roughness 0.01 } #break
    #case (2) finish { diffuse 0.7 specular 0.5 roughness 0.006 } #break
    #case (3) finish { specular 0.8 roughness 0.003 metallic } #break
    #case (5) normal { bumps 0.3 scale 0.0008 } finish { diffuse 0.8 } #break
    #case (7) finish { diffuse 0.8 specular 0.2 } #break
    #else finish { diffuse 0.6 specular 0.5 roughness 0.004 }
  #end
#end
// T lets light through for the sub-frame copies of a stick that turns while the shutter is open
// (0: the solid stick).
#macro CueStickT(T)
  union {
    #for (I, 0, CueParts - 1)
      object { CuePart(I) pigment { CueColour(I, T) } CueFinish(I) }
    #end
  }
#end
#declare CueStick = CueStickT(0)
// The shadow of a blurred stick: one unseen stick at the frame's instant, as for a ball.
#declare CueShadow = object { CueStick no_image no_reflection }

// A fast stroke's stick (pov_frame.h): one stick stretched over the way its tip goes along its axis
// while the shutter is open, from Front to Back (m along x from the tip at the frame's instant). Its
// front lets through what the stick does not cover of the shutter's time at that point of its axis,
// StickCover(x), which the frame declares as a sum of StickPiece terms: a piece of the way from A
// to B taking share S of the shutter, of which the point is covered while the tip lies in
// [x - CueLength, x] (a piece shorter than kStreakLeast, a tip at rest, taken as that long). Its
// back lets all through, so each point counts once. Its shape is the stick at Front with the butt
// drawn on to Back: the union of the stick's places, as the stick widens towards the butt. Its
// colours are the stick's averaged over the instants StickShift (weights StickShiftWeight), so the
// ferrule and the joint smear along the way as the shutter sees them; beyond its ends the stick's
// colours are its ends' own (they show only where it is mostly clear). Its finishes are its parts'
// at the frame's instant.
#declare StickPiece = function(X, A, B, S) {
  S * max(0, min(max(max(A, B), min(A, B) + 1e-4), X) - max(min(A, B), X - CueLength))
    / (max(max(A, B), min(A, B) + 1e-4) - min(A, B))
}
// The stick's colours along x as a pigment's body, letting T through.
#macro CueColours(T)
  function { min(max(x / CueLength, 0), 1) }
  pigment_map {
    #for (I, 0, CueParts - 1)
      [max(CuePartStart[I], 0) / CueLength CueColour(I, T)]
      [CuePartEnd[I] / CueLength CueColour(I, T)]
    #end
  }
#end
#macro CueSmear(T)
  average
  pigment_map {
    #for (K, 0, dimension_size(StickShift, 1) - 1)
      [StickShiftWeight[K] CueColours(T) translate StickShift[K] * x]
    #end
  }
#end
#macro CueSweep(Front, Back)
  #local Clear = pigment { CueSmear(1) }
  #local Solid = pigment { CueSmear(0) }
  #local Cover = pigment { function { min(max(StickCover(x), 0), 1) } pigment_map { [0 Clear] [1 Solid] } }
  merge {
    #for (I, 0, CueParts - 1)
      object { CuePart(I) translate Front * x }
    #end
    #if (Back > Front + 1e-6)
      cylinder { <CueLength + Front, 0, 0>, <CueLength + Back, 0, 0>, CuePartR1[CueParts - 1] }
    #end
    texture {
      function { min(max(x / CueLength, 0), 1) }
      texture_map {
        #for (I, 0, CueParts - 1)
          [max(CuePartStart[I], 0) / CueLength pigment { Cover } CueFinish(I)]
          [CuePartEnd[I] / CueLength pigment { Cover } CueFinish(I)]
        #end
      }
    }
    interior_texture { pigment { rgbt 1 } }
    no_shadow
  }
#end

// ---- the room: wide dark oak boards, walls panelled in dark wood to a chair rail with deep red
// paper above, a dark ceiling; on the walls framed pictures, a cue rack and brass sconces.
#declare RoomMin = <OuterMin.u - RoomMargin, OuterMin.v - RoomMargin>;
#declare RoomMax = <OuterMax.u + RoomMargin, OuterMax.v + RoomMargin>;
#declare WainscotTop = FloorZ + 1.0;
plane { -z, -CeilingZ pigment { srgb <0.09, 0.08, 0.07> } finish { diffuse 0.6 } }
// the four walls: panels (raised frames every 0.6 m) below the chair rail, paper above
#declare P_Wall = pigment {
  gradient z
  pigment_map {
    [0.0 srgb <0.12, 0.06, 0.03>]
    [(WainscotTop - FloorZ) / 3 srgb <0.12, 0.06, 0.03>]
    [(WainscotTop - FloorZ) / 3 srgb <0.30, 0.06, 0.05>]
    [1.0 srgb <0.30, 0.06, 0.05>]
  }
  scale 3 translate z * FloorZ
}
#macro WallPiece(Obj)  // an object built against the wall at x = 0 facing +x, placed on each wall
  object { Obj translate x * RoomMin.u }
  object { Obj rotate z * 180 translate x * RoomMax.u }
  object { Obj rotate z * 90 translate y * RoomMin.v }
  object { Obj rotate z * -90 translate y * RoomMax.v }
#end
// a chair rail and a skirting board all round
#declare Trim = union {
  box { <0, -100, WainscotTop - 0.03>, <0.03, 100, WainscotTop + 0.01> }
  box { <0, -100, FloorZ>, <0.02, 100, FloorZ + 0.12> }
  texture { T_DarkWood }
}
WallPiece(Trim)
// a framed picture W x H, centred at (0, Y, Z) on the wall x = 0: a dark canvas of soft shapes
#macro Picture(Y, Z, W, H, Seed)
  union {
    difference {
      box { <0, Y - W / 2 - 0.06, Z - H / 2 - 0.06>, <0.04, Y + W / 2 + 0.06, Z + H / 2 + 0.06> }
      box { <0.02, Y - W / 2, Z - H / 2>, <0.1, Y + W / 2, Z + H / 2> }
      pigment { srgb <0.45, 0.33, 0.14> } finish { diffuse 0.6 specular 0.5 roughness 0.01 metallic }
    }
    box { <0.01, Y - W / 2, Z - H / 2>, <0.025, Y + W / 2, Z + H / 2>
      pigment { wrinkles turbulence 0.6 color_map { [0 srgb <0.10, 0.12, 0.10>] [0.5 srgb <0.35, 0.27, 0.15>] [1 srgb <0.55, 0.45, 0.30>] }
                scale <1, W / 2, H / 2> translate Seed }
      finish { diffuse 0.7 }
    }
  }
#end
// a cue rack: a board with a row of cues standing in it
#declare CueRack = union {
  box { <0, -0.45, FloorZ + 0.25>, <0.03, 0.45, FloorZ + 0.32> texture { T_DarkWood } }
  box { <0, -0.45, FloorZ + 1.35>, <0.05, 0.45, FloorZ + 1.42> texture { T_DarkWood } }
  #for (I, 0, 7)
    cone { <0.05, -0.38 + I * 0.108, FloorZ + 0.27>, 0.0145, <0.05, -0.38 + I * 0.108, FloorZ + 1.72>, 0.0065
      pigment { gradient z color_map { [0 srgb 0.03] [0.2 srgb 0.03] [0.2 srgb <0.30, 0.12, 0.05>] [0.5 srgb <0.30, 0.12, 0.05>]
                                       [0.5 srgb <0.80, 0.66, 0.46>] [1 srgb <0.84, 0.72, 0.52>] }
                scale 1.45 translate z * (FloorZ + 0.27) }
      finish { diffuse 0.7 specular 0.4 roughness 0.01 } }
  #end
}
// a brass wall sconce with a warm shade that glows brighter than white (the develop stage gives it a
// lens glare, as a lit lampshade has in a photograph); its own light is shadowless and fades within a
// metre or two
#declare SconceY = 2.2;  // m either side of the wall's middle
#declare SconceZ = FloorZ + 1.75;
#macro Sconce(Y, Z)
  union {
    cylinder { <0, Y, Z - 0.02>, <0.12, Y, Z - 0.02>, 0.008 pigment { srgb <0.6, 0.45, 0.2> } finish { specular 0.6 roughness 0.01 metallic } }
    cone { <0.14, Y, Z - 0.06>, 0.07, <0.14, Y, Z + 0.08>, 0.045 open
      pigment { srgb <1.0, 0.75, 0.45> } finish { emission 3 diffuse 0.3 } no_shadow }
  }
#end
#declare WallDecor = union {
  Picture(-1.2, FloorZ + 1.65, 0.7, 0.5, <0.3, 1.7, 0>)
  Picture(1.2, FloorZ + 1.65, 0.7, 0.5, <2.1, 0.4, 0>)
  Sconce(-SconceY, SconceZ)
  Sconce(SconceY, SconceZ)
  object { CueRack }
}
// The walls with what hangs on them, in a light group with the sconces' own light: each sconce
// washes the wall round it in a warm scallop, as a wall light does in a photograph of a dim room (a
// point light close to the wall, fading within a few tens of centimetres), and lights nothing else;
// the lamp and the fill light the walls too.
#macro SconceWash(Y, Z)
  light_source { <0.16, Y, Z> srgb <1.0, 0.78, 0.52> * 2.5 fade_distance 0.4 fade_power 2 shadowless }
#end
light_group {
  box { <RoomMin.u, RoomMin.v, FloorZ - 0.1>, <RoomMax.u, RoomMax.v, CeilingZ + 0.1> inverse
    pigment { P_Wall } normal { bumps 0.05 scale 0.01 } finish { diffuse 0.7 }
  }
  WallPiece(union { object { WallDecor } SconceWash(-SconceY, SconceZ) SconceWash(SconceY, SconceZ) })
  global_lights on
}
// The sconces' glow on the wall through P, turned by R: one light between the two. Its light reaches
// the balls' sides that face the room, so it is a pale warm white, as a photograph balanced for the
// room shows it: an orange one turned the white cue ball tan.
#macro WallLights(P, R)
  light_source { <0.25, 0, FloorZ + 1.8> srgb <1.0, 0.9, 0.78> * 1.1 fade_distance 1.3 fade_power 2 shadowless rotate z * R translate P }
#end

// ---- the lamp: a long shade, tapered sides under a hipped roof, dark green enamel outside, white inside, a brass rim and
// two rods to the ceiling; a frosted diffuser glows in its mouth (the lamp the balls mirror).
#declare ShadeTaper = 0.07;  // m the shade's sides are drawn in on each side, rim to eaves
#declare RoofPitch = 28;     // deg: from the eaves a hipped roof rises to a ridge along the lamp
#declare EavesZ = LampTopZ - (LampHalf.v - ShadeTaper) * tan(radians(RoofPitch));
#macro ShadeSolid(Grow, Lift)
  #local TopY = LampHalf.v + Grow - ShadeTaper;
  #local TopX = LampHalf.u + Grow - ShadeTaper;
  #local Roof = <0, sin(radians(RoofPitch)), cos(radians(RoofPitch))>;
  intersection {
    box { <-LampHalf.u - Grow, -LampHalf.v - Grow, LampZ + Lift>, <LampHalf.u + Grow, LampHalf.v + Grow, LampTopZ + Lift> }
    plane { <0, EavesZ - LampZ, ShadeTaper>, 0 translate <0, LampHalf.v + Grow, LampZ> }
    plane { <0, -(EavesZ - LampZ), ShadeTaper>, 0 translate <0, -LampHalf.v - Grow, LampZ> }
    plane { <EavesZ - LampZ, 0, ShadeTaper>, 0 translate <LampHalf.u + Grow, 0, LampZ> }
    plane { <-(EavesZ - LampZ), 0, ShadeTaper>, 0 translate <-LampHalf.u - Grow, 0, LampZ> }
    plane { Roof, 0 translate <0, TopY, EavesZ + Lift> }
    plane { Roof * <1, -1, 1>, 0 translate <0, -TopY, EavesZ + Lift> }
    plane { <Roof.y, 0, Roof.z>, 0 translate <TopX, 0, EavesZ + Lift> }
    plane { <-Roof.y, 0, Roof.z>, 0 translate <-TopX, 0, EavesZ + Lift> }
  }
#end
union {
  difference {
    ShadeSolid(0, 0)
    object { ShadeSolid(-LampWall / 2, -LampWall) }
    texture { pigment { srgb <0.05, 0.24, 0.12> } finish { diffuse 0.6 specular 0.5 roughness 0.02 reflection { 0.02, 0.3 fresnel } conserve_energy } }
    interior { ior 1.5 }
    interior_texture { pigment { srgb 0.8 } finish { diffuse 0.8 emission 0.15 } }
  }
  difference {
    box { <-LampHalf.u - 0.004, -LampHalf.v - 0.004, LampZ - 0.002>, <LampHalf.u + 0.004, LampHalf.v + 0.004, LampZ + 0.016> }
    box { <-LampHalf.u + 0.01, -LampHalf.v + 0.01, LampZ - 0.01>, <LampHalf.u - 0.01, LampHalf.v - 0.01, LampZ + 0.03> }
    pigment { srgb <0.75, 0.58, 0.28> } finish { diffuse 0.5 specular 0.7 roughness 0.005 metallic }
  }
  cylinder { <-0.6 * LampHalf.u, 0, LampTopZ>, <-0.6 * LampHalf.u, 0, CeilingZ>, LampCordR
    pigment { srgb <0.6, 0.45, 0.2> } finish { specular 0.6 roughness 0.01 metallic } }
  cylinder { <0.6 * LampHalf.u, 0, LampTopZ>, <0.6 * LampHalf.u, 0, CeilingZ>, LampCordR
    pigment { srgb <0.6, 0.45, 0.2> } finish { specular 0.6 roughness 0.01 metallic } }
  // the diffuser, bright enough that its mirror image on a ball reads as the lamp
  box { <-LampHalf.u + LampWall, -LampHalf.v + LampWall, LampZ + 0.012>, <LampHalf.u - LampWall, LampHalf.v - LampWall, LampZ + 0.014>
    pigment { srgb 1 } finish { emission 9 diffuse 0 } }
  no_shadow
  translate <Middle.u, Middle.v, 0>
}

// ---- lights. The lamp: a spotlight cone from the diffuser (the shade cuts it off, so the room
// outside the cone is not tested for shadows at all) and its light fades with distance squared from
// 1.2 m. Final: an area light the size of the diffuser, without jitter (jitter flickers from frame to
// frame); draft: two point lights.
// A warm white (about 3500 K) as a photograph balanced for the room shows it: warm, not orange.
#declare LampColour = srgb <1.0, 0.95, 0.87>;
#declare LampPower = 2.9;
#macro LampCone()
  spotlight point_at <Middle.u, Middle.v, 0> radius 24 falloff 60 tightness 0
  fade_distance 1.2 fade_power 2
#end
#if (Final)
  light_source { <Middle.u, Middle.v, LampZ + 0.01> LampColour * LampPower
    area_light x * 2 * (LampHalf.u - LampWall), y * 2 * (LampHalf.v - LampWall), 5, 5 adaptive 0
    LampCone()
  }
#else
  light_source { <Middle.u - 0.6 * LampHalf.u, Middle.v, LampZ + 0.01> LampColour * LampPower / 2 LampCone() }
  light_source { <Middle.u + 0.6 * LampHalf.u, Middle.v, LampZ + 0.01> LampColour * LampPower / 2 LampCone() }
#end
// the cloth's bounce: green light from below the bed, upward, on the balls' undersides, the
// cushions' faces, the lamp's underside and the ceiling; shadowless, so it costs no shadow rays
light_source { <Middle.u, Middle.v, -0.35> srgb <0.10, 0.30, 0.16> * 0.55
  spotlight point_at <Middle.u, Middle.v, 1> radius 60 falloff 88 tightness 0
  fade_distance 0.8 fade_power 2 shadowless }
// The room's fills: the sconces' glow on each wall, and a faint fill, a hair warm, from high in two
// corners (the dim rest of the room).
#macro RoomFills()
  WallLights(x * RoomMin.u, 0)
  WallLights(x * RoomMax.u, 180)
  WallLights(y * RoomMin.v, 90)
  WallLights(y * RoomMax.v, -90)
  light_source { <RoomMin.u + 0.5, RoomMin.v + 0.5, CeilingZ - 0.3> srgb <1.0, 0.96, 0.92> * 0.16 shadowless }
  light_source { <RoomMax.u - 0.5, RoomMax.v - 0.5, CeilingZ - 0.3> srgb <1.0, 0.96, 0.92> * 0.12 shadowless }
#end
RoomFills()
// The floor is lit by the room's fills alone. The lamp's light reaches it only in a thin ring beyond
// the table's own shadow (which falls up to about 1.2 m past the rails), yet every floor point
// inside the lamp's cone would cost the area light's shadow rays: a fifth of a wide shot's time.
light_group {
  plane { z, FloorZ
    pigment {
      gradient y
      pigment_map {
        [0.0 wood turbulence 0.08 scale <0.04, 0.04, 1> rotate y * 90 color_map { [0 srgb <0.16, 0.09, 0.05>] [1 srgb <0.21, 0.12, 0.065>] }]
        [0.985 wood turbulence 0.08 scale <0.04, 0.04, 1> rotate y * 90 color_map { [0 srgb <0.16, 0.09, 0.05>] [1 srgb <0.21, 0.12, 0.065>] }]
        [0.985 srgb 0.02] [1.0 srgb 0.02]
      }
      scale 0.14
    }
    finish { diffuse 0.7 specular 0.15 roughness 0.02 }
  }
  RoomFills()
  global_lights off
}

object { Table }
)pov";

}  // namespace

std::string_view pov_cushions_and_rails_text() { return kCushionsAndRails; }

std::string_view pov_models_text() {
  static const std::string text = std::string(kModelsHead) + std::string(kCushionsAndRails) + std::string(kModelsTail);
  return text;
}

}  // namespace bsim
