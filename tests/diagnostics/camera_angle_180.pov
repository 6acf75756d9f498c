// error: 5:59 this camera's viewing angle must be smaller than 180 degrees
// error-text: angle 190

// POV-Ray refuses this too; a fisheye or panoramic camera may see more.
camera { orthographic location <0, 0, -5> look_at 0 angle 190 }
