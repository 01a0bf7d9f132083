:- module(oro_sparql_ntriples,
          [ result_ntriples/2,          % +Result, -Text
            write_rdf_term/1            % +Term
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(apply)).
:- use_module(library(oro/sparql/oro_sparql_terms), [lexical_atom/2]).

/** <module> N-Triples results of CONSTRUCT and DESCRIBE

Writes graph(Triples), the result of a CONSTRUCT or DESCRIBE query, as
N-Triples (W3C Recommendation, 2014): one triple a line, IRIs in
`<...>`, literals quoted with their language tag or datatype, blank
nodes as `_:label`.  write_rdf_term/1 writes one term that way, for the
other writers whose terms have the same syntax (TSV, Turtle).
*/

%!  result_ntriples(+Result, -Text) is det.
%
%   Text is the graph(Triples) Result in N-Triples, a string.

result_ntriples(graph(Triples), Text) :-
    with_output_to(string(Text),
                   forall(member(rdf(S, P, O), Triples),
                          ( write_rdf_term(S), put_char(' '),
                            write_rdf_term(P), put_char(' '),
                            write_rdf_term(O), write(' .\n')
                          ))).

%!  write_rdf_term(+Term) is det.
%
%   Write the RDF term Term (an IRI, a blank node or an rdf_db literal)
%   on the current output in N-Triples syntax.  A blank node's label
%   keeps its ASCII letters and digits; any other character is written
%   `_` and its code in hexadecimal, so distinct blank nodes keep
%   distinct labels.

write_rdf_term(literal(L)) :-
    !,
    (   L = lang(Lang, Lex)
    ->  write_string(Lex),
        format('@~w', [Lang])
    ;   L = type(Type, Lex)
    ->  write_string(Lex),
        format('^^<~w>', [Type])
    ;   write_string(L)
    ).
write_rdf_term(X) :-
    rdf_is_bnode(X),
    !,
    (   atom_concat('_:', Label, X)
    ->  true
    ;   Label = X
    ),
    atom_codes(Label, Codes),
    write('_:'),
    maplist(label_char, Codes).
write_rdf_term(IRI) :-
    atom_codes(IRI, Codes),
    put_char('<'),
    maplist(iri_char, Codes),
    put_char('>').

label_char(C) :-
    (   C < 128,
        code_type(C, alnum)
    ->  put_char(C)
    ;   format('_~16r_', [C])
    ).

iri_char(C) :-
    (   ( C =< 0x20 ; memberchk(C, `<>"{}|^\`\\`) )
    ->  format('\\u~|~`0t~16r~4+', [C])
    ;   put_char(C)
    ).

write_string(Lex) :-
    lexical_atom(Lex, Atom),
    atom_codes(Atom, Codes),
    put_char('"'),
    maplist(string_char, Codes),
    put_char('"').

string_char(0'") :- !, write('\\"').
string_char(0'\\) :- !, write('\\\\').
string_char(0'\n) :- !, write('\\n').
string_char(0'\r) :- !, write('\\r').
string_char(0'\t) :- !, write('\\t').
string_char(C) :- put_char(C).
