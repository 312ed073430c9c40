// The field's grid heights on a terrain (macro_names::kHeights, macro_cells.hpp's grid_heights):
// one float a grid vertex, its height above the field's origin, (cells.x + 1) a row. The shaders
// of macro-cells that follow a terrain (GRASS_MACRO_TERRAIN) read them; included after `field`
// (GrassMacroField) is declared.
layout(set = 0, binding = 5, std430) readonly buffer FieldHeights { float field_heights[]; };

float grid_height(ivec2 vertex) { return field_heights[vertex.y * (field.cells.x + 1) + vertex.x]; }

// The ground under field point u (one unit a cell) in `cell`: the cell's two triangles
// (height_field.h), as the ground is drawn and as a copy's blades are lifted.
float grid_ground(ivec2 cell, vec2 u) {
    return height_field_quad(vec4(grid_height(cell), grid_height(cell + ivec2(1, 0)), grid_height(cell + ivec2(0, 1)),
                                  grid_height(cell + ivec2(1, 1))),
                             u - vec2(cell));
}
