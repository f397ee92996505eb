!     interfacial: end of CalculiX's own friction law
            endif
