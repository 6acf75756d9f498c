// error: 4:1 no `*/` closes this comment
// error-text: comments nest

/* one /* two */
sphere { 0, 1 }
