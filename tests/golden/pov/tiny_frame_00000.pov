// frame_00000 of tiny: t = 0.0 s
#version 3.7;
#declare CamPos = <-1.8, -1.2, 1.1>;
#include "billiards.inc"

camera {
  perspective
  location <-1.8, -1.2, 1.1>
  sky z
  up z
  right -x * image_width / image_height
  angle 55.0
  look_at <0.0, 0.0, 0.0>
}

light_group {
object { Ball(0) matrix <1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0, -0.6, 0.1, 0.028575> }  // ball 0
object { Ball(3) matrix <0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.3, 0.1, 0.028575> }  // ball 1
object { Ball(11) matrix <0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.5, -0.3, 0.028575> }  // ball 2
object { CueStick matrix <-0.422618, 0.0, 0.906308, 0.0, -1.0, 0.0, 0.906308, 0.0, 0.422618, -1.135608, 0.1, 1.118635> }
  LampLight()
  global_lights on
}
