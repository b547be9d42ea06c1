// The slide's sentence a part misses, for a reason the grader gives (course 02561 slides
// "Lighting and shading", the exercises WP04P1–P5 and the formulas they use), and our step that
// does it right. Tried in order; the first match of a reason wins.
const RULES = [
  // a sphere with a hole (read from its mesh, or seen along the orbit) before the shaders': its reason may name the vertex shader
  // a hostile page's reasons are about the page, not a sentence of the step: none is named
  { test: /reads back differs from what the browser shows|replaced or probed what the grader reads/i, slide: null },
  { test: /a hole shows|not closed/i, slide: 'Draw a solid sphere in perspective view. (A: 6.6)' },
  { test: /shader (error|does not compile)|compile|does not link|WGSL/i, slide: 'Upload parameters (k_d, L_e, and p_ℓ or I_e) as uniform vectors.', note: 'the shaders must compile first: the error above gives the line' },
  { test: /adapter|WebGPU/i, slide: 'Draw a solid sphere in perspective view. (A: 6.6)', note: 'this browser has no WebGPU adapter: try the WebGL view, or a browser with WebGPU' },
  { test: /drew nothing|no canvas|one colou?r|could not be opened|never returns|time bound|page error/i, slide: 'Draw a solid sphere in perspective view. (A: 6.6)' },
  { test: /not in perspective view/i, slide: 'Draw a solid sphere in perspective view. (A: 6.6)', note: 'an orthographic view shows the normals out to 90° at the rim' },
  { test: /normal colouring of WP04P1/i, slide: 'Given other parameters k_d, k_a, L_e, L_a as uniforms and the surface normal n as an attribute, we can calculate L_o and store it in a varying color variable.' },
  { test: /per vertex|per fragment|coarse level|fragment shader/i, slide: 'We implement it by moving our evaluation of the Phong reflection model to the fragment shader. Most importantly, we must normalize the direction vectors in the fragment shader.' },
  { test: /subdivi|coarsen|finer|level|round|silhouette/i, slide: 'Insert buttons for subdividing or coarsening the mesh (incrementing or decrementing the level of subdivision). (A: 3.6.2)' },
  { test: /back side|front face|reflection of|inside|depth|cull/i, slide: 'Now, enable the depth test. Then enable backface culling. There is no visible effect of the back face culling.' },
  // (before the orbit's: a highlight's place names the light and the eye too)
  { test: /highlight sits at the light|highlight is \d+° from where|halfway between the light and the viewer/i, slide: 'ω_o is the direction toward the observer (ω_r · ω_o = cos φ). To have ω_o in the shader, we then either need the eye point in world coordinates or all vectors in eye space (where the eye point is at the origin).' },
  { test: /orbit|turns with the camera|moves with the camera|light .*(camera|eye)/i, slide: 'Add a tick function for animation and a button for toggling orbiting of the camera around the sphere on/off; move the camera with e = (r sin α, 0, r cos α) and lookAt, and upload V so that gl_Position = P*V*pos.' },
  { test: /colou?rs? (are not|decode)|0\.5·n|2c − 1|unit normal/i, slide: 'Get the normal from the position and visualize it using the vertex color c: c_rgb = 0.5 n_xyz + 0.5 = 0.5 p_xyz + 0.5.' },
  { test: /1\/r²|fall-off|point light/i, slide: 'L_i = V I / ‖p_ℓ − x‖² (a point light\'s radiance falls off with the squared distance).' },
  { test: /pow\(0, 0\)|black spots|s = /i, slide: 'L_r,s = k_s L_i (max(ω_r · ω_o, 0))^s: with s = 0, pow(0, 0) is undefined; guard it.' },
  { test: /input event|change event|while sliding/i, slide: 'Use the input event for the sliders to get immediate response while sliding.' },
  { test: /slider|\bks\b|\bkd\b|\bLe\b|\bLa\b/i, slide: 'Upload remaining parameters for the Phong model (k_s, s, L_a) as uniform vectors. Add sliders to the webpage for modifying the different parameters.' },
  { test: /highlight|specular/i, slide: 'Update your reflection model calculations to include ambient light and highlights: L_o = L_r,d + L_r,s + L_r,a.' },
  { test: /diffuse|brightness|\|n·w_i\||two-sided|lit/i, slide: 'L_r,d = k_d L_i max(cos θ, 0) = k_d L_i max(n · ω_i, 0).' },
];

/** Our own step for a part, relative to the check page. */
export const stepLink = (part) => `../${part}/`;

/**
 * The slide's sentences behind a part's review or fail reasons: [{ reason, slide, note? }], one
 * per different sentence.
 */
export function missedSlides(reasons) {
  const out = [];
  for (const reason of reasons) {
    // (a part not graded here was not judged: it misses no sentence)
    if (/^not graded here\b/.test(reason)) continue;
    if (!/^(FAIL|REVIEW)\b/.test(reason) && !/could not|nothing|never|no canvas|time bound|missing|not found/i.test(reason)) continue;
    const rule = RULES.find((r) => r.test.test(reason));
    if (rule && rule.slide === null) continue;
    if (rule && !out.some((o) => o.slide === rule.slide)) out.push({ reason, slide: rule.slide, note: rule.note });
  }
  return out;
}
