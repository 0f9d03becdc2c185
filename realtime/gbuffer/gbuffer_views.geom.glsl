// GBuffer::renderViews where the vertex shader cannot select the viewport: each triangle passed
// through to the viewport of its instance's view (gbuffer.vert.glsl's g_ outputs).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
in vec3 g_world_position[];
flat in vec3 g_world_normal[];
in vec3 g_world_shading_normal[];
flat in uint g_material[];
flat in vec3 g_view_eye[];
flat in int g_viewport[];
flat in int g_scene_triangle[];
out vec3 world_position;
flat out vec3 world_normal;
out vec3 world_shading_normal;
flat out uint material;
flat out vec3 view_eye;
flat out int scene_triangle;

void main() {
  for (int i = 0; i < 3; ++i) {
    gl_ViewportIndex = g_viewport[0];
    gl_Position = gl_in[i].gl_Position;
    world_position = g_world_position[i];
    world_normal = g_world_normal[i];
    world_shading_normal = g_world_shading_normal[i];
    material = g_material[i];
    view_eye = g_view_eye[i];
    scene_triangle = g_scene_triangle[i];
    EmitVertex();
  }
  EndPrimitive();
}
