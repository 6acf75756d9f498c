// error: 5:19 needs `spacing` or `count`
// error-text: no photon density given

#version 3.7;
global_settings { photons { gather 20, 100 } }
