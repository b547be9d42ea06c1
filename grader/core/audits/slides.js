// The slides' sentences the audits check (course 02561 "Lighting and shading", the exercises
// WP04P1–P5 and the formulas they use), quoted as a review or a fail quotes them: each audit's meta
// names one of these (audits/index.js), and the check page and the feedback page show it under a
// reason with that audit's id.
export const SLIDE = {
  sphere: 'Draw a solid sphere in perspective view. (A: 6.6)',
  buttons: 'Insert buttons for subdividing or coarsening the mesh (incrementing or decrementing the level of subdivision). (A: 3.6.2)',
  recycle: 'Recycle the vertex buffer (see previous slide).',
  normalColour: 'Get the normal from the position and visualize it using the vertex color c: c_rgb = 0.5 n_xyz + 0.5 = 0.5 p_xyz + 0.5.',
  depthCulling: 'Now, enable the depth test. Then enable backface culling. There is no visible effect of the back face culling.',
  uniforms: 'Upload parameters (k_d, L_e, and p_ℓ or I_e) as uniform vectors.',
  gouraud: 'Given other parameters k_d, k_a, L_e, L_a as uniforms and the surface normal n as an attribute, we can calculate L_o and store it in a varying color variable.',
  diffuse: 'L_r,d = k_d L_i max(cos θ, 0) = k_d L_i max(n · ω_i, 0).',
  pointLight: 'L_i = V I / ‖p_ℓ − x‖² (a point light\'s radiance falls off with the squared distance).',
  orbit: 'Add a tick function for animation and a button for toggling orbiting of the camera around the sphere on/off; move the camera with e = (r sin α, 0, r cos α) and lookAt, and upload V so that gl_Position = P*V*pos.',
  sliders: 'Upload remaining parameters for the Phong model (k_s, s, L_a) as uniform vectors. Add sliders to the webpage for modifying the different parameters.',
  inputEvent: 'Use the input event for the sliders to get immediate response while sliding.',
  highlight: 'Update your reflection model calculations to include ambient light and highlights: L_o = L_r,d + L_r,s + L_r,a.',
  eye: 'ω_o is the direction toward the observer (ω_r · ω_o = cos φ). To have ω_o in the shader, we then either need the eye point in world coordinates or all vectors in eye space (where the eye point is at the origin).',
  guardPow: 'L_r,s = k_s L_i (max(ω_r · ω_o, 0))^s: with s = 0, pow(0, 0) is undefined; guard it.',
  phongShading: 'We implement it by moving our evaluation of the Phong reflection model to the fragment shader. Most importantly, we must normalize the direction vectors in the fragment shader.',
};
