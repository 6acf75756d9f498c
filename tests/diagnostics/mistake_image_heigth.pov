// error: 5:60 undefined identifier `image_heigth`
// error-text: did you mean `image_height`?
// POV-Ray: Parse Error: Expected 'numeric expression', undeclared identifier 'image_heigth' found instead
// Mistake: `image_height` misspelt in the camera's `right`
camera { location <0, 1, -5> look_at 0 right x*image_width/image_heigth }
