#include "shaders.h"

#include <string>
#include <vector>

#include "ball_model.h"
#include "gl_api.h"
#include "number_format.h"

namespace bsim {

namespace {

// One source per stage for every material, specialised with MATERIAL so each program stays small:
// the software rasteriser runs (and compiles) only what a material needs.
//
// Three lamps hang over the table as in a pool hall; light falls off with distance so the room
// around the table goes dark. Lighting is done in linear RGB, then encoded to sRGB. The table is lit
// per vertex (its meshes are finely tessellated and it has no sharp highlights): it covers most of
// the picture, and per-pixel lighting there would cost most of a frame on a software rasteriser.
const char* const kLighting = R"glsl(
uniform vec3 u_eye;
const vec3 kLamps[3] = vec3[3](vec3(-0.8, 0.0, 1.1), vec3(0.0, 0.0, 1.1), vec3(0.8, 0.0, 1.1));

vec3 shade(vec3 albedo, vec3 n, vec3 world, float specular, float shininess, float gloss) {
  vec3 v = normalize(u_eye - world);
  if (dot(n, v) < 0.0) n = -n;
  vec3 c = albedo * (0.07 + 0.05 * n.z);
  for (int i = 0; i < 3; ++i) {
    vec3 l = kLamps[i] - world;
    float d2 = dot(l, l);
    l *= inversesqrt(d2);
    float falloff = 1.4 / (d2 + 0.25);
    float ndl = max(dot(n, l), 0.0);
    vec3 h = normalize(l + v);
    c += falloff * ndl * (albedo * 0.45 + vec3(specular * pow(max(dot(n, h), 0.0), shininess)));
  }
  if (gloss > 0.0) {
    // A dim room above, the green cloth below: what a polished ball mirrors.
    vec3 r = reflect(-v, n);
    vec3 room = r.z > 0.0 ? vec3(0.05 + 0.25 * pow(r.z, 4.0)) : vec3(0.004, 0.03, 0.012);
    float fresnel = 0.04 + 0.96 * pow(1.0 - max(dot(n, v), 0.0), 5.0);
    c += gloss * fresnel * room;
  }
  return c;
}
)glsl";

const char* const kVertexShader = R"glsl(
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in vec3 a_color;
layout(location = 3) in vec2 a_aux;
uniform mat4 u_model;
uniform mat3 u_normal_matrix;
uniform mat4 u_view_projection;
out vec3 v_world;
out vec3 v_normal;
out vec3 v_color;
out vec2 v_aux;
out vec3 v_local;
void main() {
  vec4 world = u_model * vec4(a_position, 1.0);
  v_world = world.xyz;
  v_normal = u_normal_matrix * a_normal;
#if MATERIAL == 0
  v_color = shade(a_color, normalize(v_normal), v_world, 0.04, 12.0, 0.0);
#else
  v_color = a_color;
#endif
  v_aux = a_aux;
  v_local = a_position;
  gl_Position = u_view_projection * world;
}
)glsl";

const char* const kFragmentShader = R"glsl(
in vec3 v_world;
in vec3 v_normal;
in vec3 v_color;
in vec2 v_aux;
in vec3 v_local;
out vec4 o_color;
uniform vec3 u_color;
uniform int u_number;
uniform int u_striped;
uniform float u_alpha;
uniform sampler2D u_numbers;

const vec3 kInk = vec3(0.006, 0.006, 0.008);

vec3 ball_albedo(vec3 m) {
  float e = max(fwidth(m.y), 1e-4);
  vec3 albedo = u_color;
  if (u_striped == 1) albedo = mix(u_color, kIvory, smoothstep(0.55 - e, 0.55 + e, abs(m.y)));
  if (u_number > 0) {
    float r = length(m.xy);
    float edge = max(fwidth(r), 1e-4);
    float disc = (1.0 - smoothstep(0.48 - edge, 0.48 + edge, r)) * step(0.0, abs(m.z) - 0.5);
    albedo = mix(albedo, kIvory, disc);
    vec2 p = vec2(m.z > 0.0 ? m.x : -m.x, m.y) / 0.48;
    vec2 cell = vec2(float(u_number % 4), float(u_number / 4));
    vec2 uv = clamp(vec2(p.x, -p.y) * 0.5 + 0.5, 0.0, 1.0);
    float ink = texture(u_numbers, (cell + uv) / 4.0).r * disc;
    albedo = mix(albedo, kInk, ink);
  }
  return albedo;
}

vec3 cue_albedo(float s) {
  if (s < 0.009) return vec3(0.05, 0.11, 0.30);   // chalked tip
  if (s < 0.034) return kIvory;                   // ferrule
  if (s < 0.80) return vec3(0.73, 0.48, 0.22);    // maple shaft
  if (s < 0.82) return vec3(0.01);                // joint ring
  if (s < 1.02) return vec3(0.035, 0.012, 0.006); // ebony forearm
  if (s < 1.30) return vec3(0.012, 0.012, 0.014); // wrap
  if (s < 1.44) return vec3(0.035, 0.012, 0.006);
  return vec3(0.005);                             // bumper
}

void main() {
  vec3 c;
  float alpha = 1.0;
#if MATERIAL == 1
  c = shade(ball_albedo(normalize(v_local)), normalize(v_normal), v_world, 0.9, 90.0, 1.0);
#elif MATERIAL == 2
  c = shade(cue_albedo(v_aux.x), normalize(v_normal), v_world, 0.35, 40.0, 0.3);
#elif MATERIAL == 3
  c = u_color;
#elif MATERIAL == 4
  c = vec3(0.0);
  alpha = u_alpha * (1.0 - smoothstep(0.2, 1.0, length(v_aux)));
#else
  c = v_color;
#endif
  c = clamp(c, 0.0, 1.0);
  o_color = vec4(mix(12.92 * c, 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055, step(0.0031308, c)), alpha);
}
)glsl";

/// `object` when its `status` (compile or link) is good; otherwise 0, the object deleted and `error`
/// set to `what` and GL's log.
template <class GetStatus, class GetLog, class Delete>
unsigned checked(GLuint object, GLenum status, GetStatus get_status, GetLog get_log, Delete destroy, const char* what,
                 std::string& error) {
  GLint ok = 0;
  get_status(object, status, &ok);
  if (ok) return object;
  std::vector<char> log(4096);
  get_log(object, static_cast<GLsizei>(log.size()), nullptr, log.data());
  error = std::string(what) + log.data();
  destroy(object);
  return 0;
}

unsigned compile(GLenum kind, const char* source, std::string& error) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  return checked(shader, GL_COMPILE_STATUS, glGetShaderiv, glGetShaderInfoLog, glDeleteShader,
                 "shader does not compile: ", error);
}

/// The ball's ivory (stripes' ground, number discs, the stick's ferrule), from the core's colours.
std::string ivory_declaration() {
  const Vec3 c = ball_ivory();
  return "const vec3 kIvory = vec3(" + format_number(c.x()) + ", " + format_number(c.y()) + ", " +
         format_number(c.z()) + ");\n";
}

}  // namespace

unsigned build_scene_program(Material material, std::string& error) {
  const std::string header = "#version 330 core\n#define MATERIAL " + std::to_string(static_cast<int>(material)) +
                             "\n" + ivory_declaration() + kLighting;
  const unsigned vertex = compile(GL_VERTEX_SHADER, (header + kVertexShader).c_str(), error);
  if (!vertex) return 0;
  const unsigned fragment = compile(GL_FRAGMENT_SHADER, (header + kFragmentShader).c_str(), error);
  if (!fragment) {
    glDeleteShader(vertex);
    return 0;
  }
  const GLuint program = glCreateProgram();
  glAttachShader(program, vertex);
  glAttachShader(program, fragment);
  glLinkProgram(program);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  return checked(program, GL_LINK_STATUS, glGetProgramiv, glGetProgramInfoLog, glDeleteProgram,
                 "shader program does not link: ", error);
}

}  // namespace bsim
