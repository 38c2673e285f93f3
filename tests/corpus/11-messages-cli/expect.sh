# 11: errors that named nothing or took the wrong exit (found: "error: stoi", exit 1 "failure: stoi").
check sweep-spacing-not-a-count 2 "--sweep-spacing '1um:2um:abc': COUNT must be a whole number" -- g multi-asperity --sweep-spacing 1um:2um:abc --elements 2048
check sweep-spacing-wrapping-count 2 "--sweep-spacing '1um:2um:99999999999': COUNT" -- g multi-asperity --sweep-spacing 1um:2um:99999999999 --elements 2048
check speed-sweep-fields 2 "--speed-sweep '100rpm:200': needs three fields" -- g dynamics --speed-sweep 100rpm:200
check speed-sweep-unit 2 "--speed-sweep" -- g dynamics --speed-sweep 100xyz:200rpm:3
