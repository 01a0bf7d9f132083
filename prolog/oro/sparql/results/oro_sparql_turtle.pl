:- module(oro_sparql_turtle,
          [ result_turtle/2             % +Result, -Text
          ]).
:- use_module(library(lists)).
:- use_module(library(pairs)).
:- use_module(library(oro/sparql/results/oro_sparql_ntriples), [write_rdf_term/1]).

/** <module> Turtle results of CONSTRUCT and DESCRIBE

Writes graph(Triples), the result of a CONSTRUCT or DESCRIBE query, as
Turtle (W3C Recommendation, 2014): the triples of a subject together,
its predicates separated by `;` and the objects of a predicate by `,`;
terms are written as in N-Triples (oro_sparql_ntriples), which Turtle
reads as they are.
*/

%!  result_turtle(+Result, -Text) is det.
%
%   Text is the graph(Triples) Result in Turtle, a string.

result_turtle(graph(Triples), Text) :-
    findall(S-(P-O), member(rdf(S, P, O), Triples), Pairs),
    group_pairs_by_key(Pairs, BySubject),
    with_output_to(string(Text), forall(member(S-POs, BySubject),
                                        write_subject(S, POs))).

write_subject(S, POs) :-
    write_rdf_term(S),
    group_pairs_by_key(POs, ByPredicate),
    write_predicates(ByPredicate),
    write(' .\n').

write_predicates([P-Os|Rest]) :-
    write('\n    '),
    write_rdf_term(P),
    put_char(' '),
    write_objects(Os),
    (   Rest == []
    ->  true
    ;   write(' ;'),
        write_predicates(Rest)
    ).

write_objects([O|Os]) :-
    write_rdf_term(O),
    (   Os == []
    ->  true
    ;   write(' , '),
        write_objects(Os)
    ).
