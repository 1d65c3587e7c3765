// What the viewer takes from npm, bundled into vendor/viewer-deps.js by vendor.sh (one classic
// script, so the exported page can inline it and nothing is fetched when a match is watched).
import {
  AmbientLight, BoxGeometry, BufferGeometry, CapsuleGeometry, Color, CylinderGeometry,
  DirectionalLight, Float32BufferAttribute, Group, HemisphereLight, LineBasicMaterial,
  LineSegments, Mesh, MeshLambertMaterial, PerspectiveCamera, PlaneGeometry, Quaternion, Scene,
  SphereGeometry, Vector3, WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { decompress } from 'fzstd';

window.THREE = {
  AmbientLight, BoxGeometry, BufferGeometry, CapsuleGeometry, Color, CylinderGeometry,
  DirectionalLight, Float32BufferAttribute, Group, HemisphereLight, LineBasicMaterial,
  LineSegments, Mesh, MeshLambertMaterial, PerspectiveCamera, PlaneGeometry, Quaternion, Scene,
  SphereGeometry, Vector3, WebGLRenderer, OrbitControls,
};
window.fzstd = { decompress };
