//! Acceleration structures: the SAH bounding volume hierarchy.
