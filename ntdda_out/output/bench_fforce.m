frictionforces = [
];
