//! Render-time geometry: shapes prepared for ray intersection, CSG, and the World of objects.
