// What the course fixes for every step, named once: the clear colour and the camera.

/** The slides' clear colour (their render pass): cornflower blue, RGBA. */
export const BACKGROUND = [0.3921, 0.5843, 0.9294, 1.0];

/** The camera looks at the unit sphere's centre from EYE_DISTANCE away, FOVY degrees high. */
export const EYE_DISTANCE = 3;
export const FOVY = 45;
export const AT = [0, 0, 0];
export const UP = [0, 1, 0];

/** The orbiting camera (WP04P3 on): radians per second, one turn in 12 s. */
export const ORBIT_SPEED = (2 * Math.PI) / 12;

/**
 * Where each kind of light starts: a directional light's xyz is the direction it shines in (l_e);
 * a point light's is its position.
 */
export const LIGHT_DEFAULTS = { directional: [0, 0, -1], point: [0, 0, 2] };
