// warning: 6:10 lemon
// warning-text: 0.2 is too small
// warning-text: using 0.335

// A lemon whose inner radius is too small to bulge outwards: warned and raised.
object { lemon { 0, 0.3, y*0.3, 0.3, 0.2 } }
